/* Opens a CPACS file through Airshape's C interface, reports every wing (volume, reference
 * area, span, a point on its upper skin), then scales the first wing's tip chord by 1.2,
 * reports again and prints what the geometry cache rebuilt.
 *
 *     build/bin/airshape_wing_report examples/generic-airliner.xml */
#include <stdio.h>

#include "airshape.h"

static int failed(airshape_status status, const char* what) {
  if (status == AIRSHAPE_OK) return 0;
  fprintf(stderr, "wing_report: %s: %s: %s\n", what, airshape_status_name(status), airshape_last_error());
  return 1;
}

static int report(airshape_configuration* configuration) {
  int wings = 0;
  if (failed(airshape_wing_count(configuration, &wings), "wing count")) return 1;
  for (int wing = 1; wing <= wings; ++wing) {
    char* uid = NULL;
    double volume = 0, area = 0, span = 0, point[3] = {0, 0, 0};
    if (failed(airshape_wing_uid(configuration, wing, &uid), "wing uid") ||
        failed(airshape_wing_volume(configuration, wing, &volume), "volume") ||
        failed(airshape_wing_reference_area(configuration, wing, "x-y", &area), "reference area") ||
        failed(airshape_wing_span(configuration, wing, &span), "span") ||
        failed(airshape_wing_upper_point(configuration, wing, 1, 0.5, 0.25, point), "upper point")) {
      airshape_free(uid);
      return 1;
    }
    printf("%-8s volume %9.4f m3  reference area %9.4f m2  span %8.4f m  upper(1, 0.5, 0.25) = (%.4f, %.4f, %.4f)\n",
           uid, volume, area, span, point[0], point[1], point[2]);
    airshape_free(uid);
  }
  return 0;
}

int main(int argc, char** argv) {
  if (argc != 2) {
    fprintf(stderr, "usage: wing_report FILE.xml\n");
    return 2;
  }
  airshape_configuration* configuration = NULL;
  if (failed(airshape_open(argv[1], &configuration), "open")) return 2;
  int status = report(configuration);

  /* The tip element of the first wing's last section: scale its chord (x) by 1.2. */
  int sections = 0;
  char* uid = NULL;
  char xpath[512], *chord = NULL, scaled[64];
  if (!status && !failed(airshape_wing_section_count(configuration, 1, &sections), "sections") &&
      !failed(airshape_wing_uid(configuration, 1, &uid), "wing uid")) {
    snprintf(xpath, sizeof xpath,
             "/cpacs/vehicles/aircraft/model/wings/wing[@uID='%s']/sections/section[%d]/elements/element/"
             "transformation/scaling/x",
             uid, sections);
    if (!failed(airshape_get_value(configuration, xpath, &chord), "read the tip chord")) {
      double value = 0;
      sscanf(chord, "%lf", &value);
      snprintf(scaled, sizeof scaled, "%.15g", 1.2 * value);
      printf("tip chord of %s: %s -> %s\n", uid, chord, scaled);
      if (failed(airshape_set_value(configuration, xpath, scaled), "set the tip chord") || report(configuration))
        status = 1;
    } else {
      status = 1;
    }
    airshape_free(chord);
    airshape_free(uid);
  } else {
    status = 1;
  }

  size_t built = 0, reused = 0, invalidated = 0;
  if (!failed(airshape_cache_statistics(configuration, &built, &reused, &invalidated), "statistics"))
    printf("cache: %zu built, %zu reused, %zu invalidated\n", built, reused, invalidated);
  airshape_close(configuration);
  return status;
}
