/* The C interface, from C: statuses and messages for bad input (never a crash), every typed
 * op against the generic query, editing, exports, and handles used from several threads. */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "airshape.h"
#include "airshape_ops.h"

static int failures = 0;

#define CHECK(condition)                                                                            \
  do {                                                                                              \
    if (!(condition)) {                                                                             \
      fprintf(stderr, "%s:%d: CHECK failed: %s (last error: %s)\n", __FILE__, __LINE__, #condition, \
              airshape_last_error());                                                               \
      ++failures;                                                                                   \
    }                                                                                               \
  } while (0)

static const char* airliner;
static const char* with_devices;
static const char* with_structure;
static const char* rotorcraft;

/* The number a generic query answers. */
static double queried(airshape_configuration* c, const char* query) {
  char* result = NULL;
  double value = NAN;
  if (airshape_query(c, query, &result) == AIRSHAPE_OK) value = atof(result);
  airshape_free(result);
  return value;
}

static void bad_input_gives_statuses(void) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open("/no/such/file.xml", &c) == AIRSHAPE_FILE_NOT_FOUND);
  CHECK(c == NULL);
  CHECK(strstr(airshape_last_error(), "/no/such/file.xml") != NULL);
  CHECK(airshape_open_string("<cpacs><header>", "broken", &c) == AIRSHAPE_NOT_XML);
  CHECK(airshape_open_string("<html/>", "page", &c) == AIRSHAPE_NOT_CPACS);
  CHECK(airshape_open(NULL, &c) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(airshape_open(airliner, NULL) == AIRSHAPE_INVALID_ARGUMENT);
  double volume = 0;
  CHECK(airshape_wing_volume(NULL, 1, &volume) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strcmp(airshape_status_name(AIRSHAPE_WRITE_FAILED), "AIRSHAPE_WRITE_FAILED") == 0);
}

static void typed_ops_agree_with_the_query(void) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(airliner, &c) == AIRSHAPE_OK);
  int wings = 0, fuselages = 0, segments = 0;
  CHECK(airshape_wing_count(c, &wings) == AIRSHAPE_OK && wings == 3);
  CHECK(airshape_fuselage_count(c, &fuselages) == AIRSHAPE_OK && fuselages == 1);
  CHECK(airshape_wing_segment_count(c, 1, &segments) == AIRSHAPE_OK && segments == 2);
  char* text = NULL;
  CHECK(airshape_wing_uid(c, 2, &text) == AIRSHAPE_OK && strcmp(text, "HTP") == 0);
  airshape_free(text);
  CHECK(airshape_wing_symmetry(c, 1, &text) == AIRSHAPE_OK && strcmp(text, "x-z") == 0);
  airshape_free(text);

  double volume = 0, area = 0, span = 0, mac = 0, point[3], centre[3], minimum[3], maximum[3];
  CHECK(airshape_wing_volume(c, 1, &volume) == AIRSHAPE_OK);
  CHECK(volume == queried(c, "{\"op\":\"wing_volume\",\"wing\":\"Wing\"}"));
  CHECK(airshape_wing_reference_area(c, 1, "x-y", &area) == AIRSHAPE_OK && area > 50);
  CHECK(airshape_wing_span(c, 1, &span) == AIRSHAPE_OK && span > 30);
  CHECK(airshape_wing_mac(c, 1, &mac, centre) == AIRSHAPE_OK && mac > 1);
  CHECK(airshape_wing_surface_area(c, 1, &area) == AIRSHAPE_OK && area > 100);
  CHECK(airshape_wing_wetted_area(c, 1, &area) == AIRSHAPE_OK && area > 100);
  CHECK(airshape_wing_segment_volume(c, 1, 2, &volume) == AIRSHAPE_OK && volume > 0);
  CHECK(airshape_wing_segment_surface_area(c, 1, 2, &area) == AIRSHAPE_OK && area > 0);
  CHECK(airshape_wing_upper_point(c, 1, 1, 0.5, 0.3, point) == AIRSHAPE_OK);
  char* segment = NULL;
  double eta = 0, xsi = 0;
  int on_top = 0;
  CHECK(airshape_wing_segment_eta_xsi(c, 1, point, &segment, &eta, &xsi, &on_top) == AIRSHAPE_OK);
  CHECK(segment != NULL && fabs(eta - 0.5) < 1e-6 && fabs(xsi - 0.3) < 1e-6 && on_top == 1);
  airshape_free(segment);
  CHECK(airshape_wing_lower_point(c, 1, 1, 0.5, 0.3, point) == AIRSHAPE_OK);
  CHECK(airshape_wing_chord_point(c, 1, 1, 0.5, 0.3, point) == AIRSHAPE_OK);
  CHECK(airshape_fuselage_point(c, 1, 4, 0.5, 0.25, point) == AIRSHAPE_OK && fabs(point[1] - 2.0) < 1e-3);
  CHECK(airshape_fuselage_volume(c, 1, &volume) == AIRSHAPE_OK && volume > 300);
  CHECK(airshape_fuselage_surface_area(c, 1, &area) == AIRSHAPE_OK && area > 300);
  CHECK(airshape_fuselage_segment_volume(c, 1, 4, &volume) == AIRSHAPE_OK && volume > 200);
  CHECK(airshape_fuselage_segment_surface_area(c, 1, 4, &area) == AIRSHAPE_OK && area > 200);
  CHECK(airshape_fuselage_circumference(c, 1, 4, 0.5, &area) == AIRSHAPE_OK && fabs(area - 4 * M_PI) < 0.05);
  CHECK(airshape_fuselage_segment_count(c, 1, &segments) == AIRSHAPE_OK && segments == 7);
  CHECK(airshape_fuselage_uid(c, 1, &text) == AIRSHAPE_OK && strcmp(text, "Fuselage") == 0);
  airshape_free(text);
  CHECK(airshape_bounding_box(c, NULL, minimum, maximum) == AIRSHAPE_OK && maximum[1] == -minimum[1]);
  CHECK(airshape_bounding_box(c, "VTP", minimum, maximum) == AIRSHAPE_OK && minimum[2] > 0);
  int component_segments = -1;
  CHECK(airshape_wing_component_segment_count(c, 1, &component_segments) == AIRSHAPE_OK && component_segments == 1);
  CHECK(airshape_component_segment_to_segment(c, 1, 1, 0.5, 0.5, NULL, &eta, &xsi) == AIRSHAPE_OK && eta >= 0 &&
        eta <= 1 && xsi >= 0 && xsi <= 1);

  /* Bad arguments: statuses and messages, and the handle goes on working. */
  CHECK(airshape_wing_upper_point(c, 1, 1, 1.5, 0.3, point) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strstr(airshape_last_error(), "eta") != NULL);
  CHECK(airshape_wing_volume(c, 9, &volume) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(airshape_component_segment_to_segment(c, 1, 2, 0.5, 0.5, NULL, &eta, &xsi) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(airshape_query(c, "not json", &text) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(airshape_wing_volume(c, 1, &volume) == AIRSHAPE_OK);
  airshape_close(c);
}

/* The size of a file in bytes, -1 when it cannot be opened. */
static long file_size(const char* path) {
  FILE* file = fopen(path, "rb");
  if (!file) return -1;
  fseek(file, 0, SEEK_END);
  const long size = ftell(file);
  fclose(file);
  return size;
}

static void editing_and_exporting(const char* folder) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(airliner, &c) == AIRSHAPE_OK);
  const char* chord =
      "/cpacs/vehicles/aircraft/model/wings/wing[@uID='HTP']/sections/section[2]/elements/element/"
      "transformation/scaling/x";
  double before = 0, after = 0;
  CHECK(airshape_wing_volume(c, 2, &before) == AIRSHAPE_OK);
  CHECK(airshape_set_value(c, chord, "wide") == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(airshape_set_value(c, chord, "2.8") == AIRSHAPE_OK);
  char* value = NULL;
  CHECK(airshape_get_value(c, chord, &value) == AIRSHAPE_OK && strcmp(value, "2.8") == 0);
  airshape_free(value);
  CHECK(airshape_wing_volume(c, 2, &after) == AIRSHAPE_OK && after > before);
  size_t built = 0, reused = 0, invalidated = 0;
  CHECK(airshape_cache_statistics(c, &built, &reused, &invalidated) == AIRSHAPE_OK && invalidated > 0);

  /* The HTP's outer segment out and back in. */
  const char* segment = "/cpacs/vehicles/aircraft/model/wings/wing[@uID='HTP']/segments/segment";
  char* uid = NULL;
  int segments = 0;
  CHECK(airshape_get_value(c, "/cpacs/vehicles/aircraft/model/wings/wing[@uID='HTP']/segments/segment/@uID", &uid) ==
        AIRSHAPE_OK);
  CHECK(uid != NULL && strcmp(uid, "HTP_Seg1") == 0);
  airshape_free(uid);
  CHECK(airshape_remove(c, segment) == AIRSHAPE_OK);
  CHECK(airshape_wing_segment_count(c, 2, &segments) == AIRSHAPE_OK && segments == 0);
  CHECK(airshape_insert_xml(c, "/cpacs/vehicles/aircraft/model/wings/wing[@uID='HTP']/segments",
                            "<segment uID=\"HTP_Seg1\"><name>back</name><fromElementUID>HTP_S1_E</fromElementUID>"
                            "<toElementUID>HTP_S2_E</toElementUID></segment>",
                            0) == AIRSHAPE_OK);
  CHECK(airshape_wing_segment_count(c, 2, &segments) == AIRSHAPE_OK && segments == 1);
  CHECK(airshape_insert_xml(c, "/cpacs/vehicles/aircraft/model/wings", "<wing", 0) == AIRSHAPE_NOT_XML);
  CHECK(airshape_remove(c, "/cpacs/vehicles/aircraft/model/wings/wing[9]") == AIRSHAPE_INVALID_ARGUMENT);

  char path[1024];
  snprintf(path, sizeof path, "%s/htp.stl", folder);
  CHECK(airshape_export(c, path, "HTP", 1, 0, 0, 0) == AIRSHAPE_OK);
  snprintf(path, sizeof path, "%s/no/such/folder/x.step", folder);
  CHECK(airshape_export(c, path, NULL, 0, 0, 0, 0) == AIRSHAPE_WRITE_FAILED);
  /* A coarse surface mesh (docs/meshing.md): the report names it; a malformed option is refused. */
  char* report = NULL;
  snprintf(path, sizeof path, "%s/c_api_surface.vtu", folder);
  CHECK(airshape_mesh(c, path, "--size 3 --components HTP,VTP", &report) == AIRSHAPE_OK);
  CHECK(report != NULL && strstr(report, "\"name\":\"surface\"") != NULL && file_size(path) > 0);
  airshape_free(report);
  CHECK(airshape_mesh(c, path, "--size -1", &report) == AIRSHAPE_INVALID_ARGUMENT);
  /* A frame with its Z profile swept along it: surfaces, a much larger file than its line. */
  char line_path[1024], swept_path[1024];
  snprintf(line_path, sizeof line_path, "%s/c_api_frame_line.brep", folder);
  snprintf(swept_path, sizeof swept_path, "%s/c_api_frame_swept.brep", folder);
  remove(line_path);
  remove(swept_path);
  CHECK(airshape_export(c, line_path, "Frame_Door_Front", 0, 0, 0, 0) == AIRSHAPE_OK);
  CHECK(airshape_export_profiles(c, swept_path, "Frame_Door_Front") == AIRSHAPE_OK);
  CHECK(file_size(swept_path) > 3 * file_size(line_path));
  snprintf(path, sizeof path, "%s/edited.xml", folder);
  CHECK(airshape_save(c, path) == AIRSHAPE_OK);
  airshape_close(c);
  CHECK(airshape_open(path, &c) == AIRSHAPE_OK);
  CHECK(airshape_wing_volume(c, 2, &before) == AIRSHAPE_OK && fabs(before - after) < 1e-12 * after);
  airshape_close(c);
}

struct job {
  airshape_configuration* shared;
  double own[20][3], through_shared[20][3];
  airshape_status status;
};

static void* work(void* argument) {
  struct job* job = argument;
  airshape_configuration* own = NULL;
  job->status = airshape_open(airliner, &own);
  for (int i = 0; i < 20 && job->status == AIRSHAPE_OK; ++i) {
    job->status = airshape_wing_upper_point(own, 1, 2, i / 19.0, 0.4, job->own[i]);
    if (job->status == AIRSHAPE_OK)
      job->status = airshape_wing_upper_point(job->shared, 1, 2, i / 19.0, 0.4, job->through_shared[i]);
  }
  airshape_close(own);
  return NULL;
}

static void handles_work_from_several_threads(void) {
  airshape_configuration* shared = NULL;
  CHECK(airshape_open(airliner, &shared) == AIRSHAPE_OK);
  struct job jobs[4];
  pthread_t threads[4];
  for (int t = 0; t < 4; ++t) {
    jobs[t].shared = shared;
    pthread_create(&threads[t], NULL, work, &jobs[t]);
  }
  for (int t = 0; t < 4; ++t) pthread_join(threads[t], NULL);
  for (int t = 0; t < 4; ++t) {
    CHECK(jobs[t].status == AIRSHAPE_OK);
    CHECK(memcmp(jobs[t].own, jobs[0].own, sizeof jobs[t].own) == 0);
    CHECK(memcmp(jobs[t].through_shared, jobs[0].own, sizeof jobs[t].own) == 0);
  }
  airshape_close(shared);
}

/* The rectangular wing with a flap, a slat and a spoiler: devices listed, ranges, the flap's
 * motion (20 degrees about its hinge line on the chord at x = 2.4), an export with them deflected.
 * (It also has a tab on the flap, listed after it.) */
static void control_devices(const char* folder) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(with_devices, &c) == AIRSHAPE_OK);
  int count = 0;
  char* uid = NULL;
  CHECK(airshape_control_surface_count(c, 1, &count) == AIRSHAPE_OK && count == 3);
  CHECK(airshape_control_surface_uid(c, 1, 1, &uid) == AIRSHAPE_OK && strcmp(uid, "Flap") == 0);
  airshape_free(uid);
  CHECK(airshape_spoiler_count(c, 1, &count) == AIRSHAPE_OK && count == 1);
  CHECK(airshape_spoiler_uid(c, 1, 1, &uid) == AIRSHAPE_OK && strcmp(uid, "Spoiler") == 0);
  airshape_free(uid);
  double minimum = NAN, maximum = NAN, matrix[12], rotation = NAN;
  CHECK(airshape_control_surface_range(c, "Flap", &minimum, &maximum) == AIRSHAPE_OK && minimum == 0 && maximum == 1);
  CHECK(airshape_control_surface_motion(c, "Flap", 1.0, matrix, &rotation) == AIRSHAPE_OK);
  CHECK(fabs(rotation - 20) < 1e-9 && fabs(matrix[2] - sin(20 * M_PI / 180)) < 1e-12);
  CHECK(fabs(matrix[3] - (2.4 - 2.4 * cos(20 * M_PI / 180))) < 1e-12);
  CHECK(airshape_control_surface_motion(c, "Flap", 2.0, matrix, &rotation) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strstr(airshape_last_error(), "outside the range") != NULL);

  char path[4096];
  snprintf(path, sizeof path, "%s/c_api_deflected.brep", folder);
  remove(path);
  CHECK(airshape_export_deflected(c, path, "Rect", "Flap=1,Slat=max", 0, 0, 0, 0) == AIRSHAPE_OK);
  FILE* written = fopen(path, "r");
  CHECK(written != NULL);
  if (written) fclose(written);
  CHECK(airshape_export_deflected(c, path, "Rect", "Rect=1", 0, 0, 0, 0) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strstr(airshape_last_error(), "names no moving component") != NULL);
  airshape_close(c);
}

/* Structure by uID: a spar web's type, volume (none: it is a surface) and area in closed form,
 * the components inside a component segment, and the structural model written. */
static void structure_components(const char* folder) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(with_structure, &c) == AIRSHAPE_OK);
  char* text = NULL;
  double volume = NAN, area = NAN;
  CHECK(airshape_component_type(c, "Front", &text) == AIRSHAPE_OK && strcmp(text, "wing_spar") == 0);
  airshape_free(text);
  CHECK(airshape_component_volume(c, "Front", &volume) == AIRSHAPE_OK && volume == 0);
  CHECK(airshape_component_surface_area(c, "Front", &area) == AIRSHAPE_OK && fabs(area - 0.48) < 1e-7);
  CHECK(airshape_component_children(c, "RectCS", &text) == AIRSHAPE_OK);
  CHECK(text != NULL && strstr(text, "\"Rear\"") != NULL && strstr(text, "\"wing_rib\"") != NULL);
  airshape_free(text);
  CHECK(airshape_component_type(c, "Nowhere", &text) == AIRSHAPE_INVALID_ARGUMENT);
  char path[4096];
  snprintf(path, sizeof path, "%s/c_api_wing_box.brep", folder);
  remove(path);
  CHECK(airshape_export_structure(c, path, "Rect") == AIRSHAPE_OK);
  FILE* written = fopen(path, "r");
  CHECK(written != NULL);
  if (written) fclose(written);
  airshape_close(c);
}

/* The two-bladed rotor of rectangular blades (chord 0.3, from 0.5 m to 4.5 m off the hub, 300 rpm):
 * its figures in closed form. */
static void rotors(void) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(rotorcraft, &c) == AIRSHAPE_OK);
  int count = 0;
  char* uid = NULL;
  double radius = NAN, planform = NAN, solidity = NAN, tip = NAN, volume = NAN;
  CHECK(airshape_rotor_count(c, &count) == AIRSHAPE_OK && count == 3);
  CHECK(airshape_rotor_uid(c, 1, &uid) == AIRSHAPE_OK && strcmp(uid, "Main") == 0);
  airshape_free(uid);
  CHECK(airshape_rotor_blade_count(c, 1, &count) == AIRSHAPE_OK && count == 2);
  CHECK(airshape_rotor_radius(c, 1, &radius) == AIRSHAPE_OK && fabs(radius - hypot(0.075, 4.5)) < 1e-12);
  CHECK(airshape_rotor_total_blade_planform_area(c, 1, &planform) == AIRSHAPE_OK && fabs(planform - 2.4) < 1e-12);
  CHECK(airshape_rotor_solidity(c, 1, &solidity) == AIRSHAPE_OK &&
        fabs(solidity - 2.4 / (M_PI * radius * radius)) < 1e-12);
  CHECK(airshape_rotor_tip_speed(c, 1, &tip) == AIRSHAPE_OK && fabs(tip - 10 * M_PI * radius) < 1e-9);
  CHECK(airshape_rotor_volume(c, 1, &volume) == AIRSHAPE_OK && fabs(volume - 0.036) < 1e-7);
  CHECK(airshape_rotor_radius(c, 3, &radius) == AIRSHAPE_INVALID_MODEL);
  CHECK(strstr(airshape_last_error(), "rotorBladeUID") != NULL);
  airshape_close(c);
}

/* Duct cut-outs are off when a file is opened; on, the airliner's APU duct takes out of its fuselage. */
static void duct_cutouts(void) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(airliner, &c) == AIRSHAPE_OK);
  int on = -1;
  CHECK(airshape_get_option(c, "duct_cutouts", &on) == AIRSHAPE_OK && on == 0);
  double clean = 0.0, cut = 0.0, again = 0.0;
  CHECK(airshape_fuselage_volume(c, 1, &clean) == AIRSHAPE_OK);
  CHECK(airshape_set_duct_cutouts(c, 1) == AIRSHAPE_OK);
  CHECK(airshape_get_option(c, "duct_cutouts", &on) == AIRSHAPE_OK && on == 1);
  CHECK(airshape_fuselage_volume(c, 1, &cut) == AIRSHAPE_OK);
  CHECK(cut < clean - 0.01);
  CHECK(airshape_set_option(c, "duct_cutouts", 0) == AIRSHAPE_OK);
  CHECK(airshape_fuselage_volume(c, 1, &again) == AIRSHAPE_OK && again == clean);
  CHECK(airshape_set_option(c, "no_such_option", 1) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strstr(airshape_last_error(), "no build option 'no_such_option'") != NULL);
  CHECK(airshape_get_option(c, "no_such_option", &on) == AIRSHAPE_INVALID_ARGUMENT);
  airshape_close(c);
}

/* The functions generated from the query registry (airshape_ops.h): each op with its arguments,
 * its result as JSON, the same text airshape_query gives. */
static void generated_op_functions(void) {
  airshape_configuration* c = NULL;
  CHECK(airshape_open(airliner, &c) == AIRSHAPE_OK);
  char* generated = NULL;
  char* queried_text = NULL;
  CHECK(airshape_op_wing_span(c, 1, &generated) == AIRSHAPE_OK);
  CHECK(airshape_query(c, "{\"op\":\"wing_span\",\"wing\":1}", &queried_text) == AIRSHAPE_OK);
  CHECK(generated != NULL && queried_text != NULL && strcmp(generated, queried_text) == 0);
  airshape_free(generated);
  airshape_free(queried_text);
  const double point[3] = {20.0, 0.0, 0.0}, normal[3] = {1.0, 0.0, 0.0};
  CHECK(airshape_op_cross_section_area(c, "Fuselage", point, normal, &generated) == AIRSHAPE_OK);
  CHECK(generated != NULL && atof(generated) > 1.0);
  airshape_free(generated);
  const int mirrored = 1; /* an optional argument: a pointer, NULL leaves it out */
  CHECK(airshape_op_component_faces(c, "Wing", &mirrored, &generated) == AIRSHAPE_OK);
  CHECK(generated != NULL && strstr(generated, "\"name\"") != NULL);
  airshape_free(generated);
  CHECK(airshape_op_bounding_box(c, NULL, &generated) == AIRSHAPE_OK && strstr(generated, "\"min\"") != NULL);
  airshape_free(generated);
  CHECK(airshape_op_wing_span(c, 9, &generated) == AIRSHAPE_INVALID_ARGUMENT);
  CHECK(strstr(airshape_last_error(), "wing") != NULL);
  airshape_close(c);
}

int main(int argc, char** argv) {
  if (argc != 6) {
    fprintf(stderr,
            "usage: c_api_test AIRLINER.xml WRITABLE_FOLDER WING_WITH_DEVICES.xml WING_WITH_STRUCTURE.xml "
            "ROTORCRAFT.xml\n");
    return 2;
  }
  rotorcraft = argv[5];
  with_structure = argv[4];
  airliner = argv[1];
  with_devices = argv[3];
  bad_input_gives_statuses();
  typed_ops_agree_with_the_query();
  editing_and_exporting(argv[2]);
  handles_work_from_several_threads();
  control_devices(argv[2]);
  structure_components(argv[2]);
  rotors();
  duct_cutouts();
  generated_op_functions();
  if (failures == 0) printf("c_api_test: all checks passed\n");
  return failures == 0 ? 0 : 1;
}
