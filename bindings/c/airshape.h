/* Airshape's C interface: CPACS configurations as exact geometry, from C, Fortran, MATLAB,
 * Java (JNA) or any language that calls C.
 *
 * Every function returns an airshape_status; AIRSHAPE_OK is 0. On any other status,
 * airshape_last_error() gives a one-line message (the file and the CPACS path included
 * where known) for the calling thread. No C++ exception crosses this interface.
 *
 * A configuration handle may be used from one thread at a time (calls on one handle are
 * serialised by a lock); different handles may be used from different threads at once.
 * Components and segments are addressed by 1-based index; airshape_query() takes any op of
 * the query protocol (docs/query.md) with uIDs as well. Strings returned through char**
 * are allocated by Airshape and freed with airshape_free(). */
#ifndef AIRSHAPE_H
#define AIRSHAPE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct airshape_configuration airshape_configuration;

typedef enum airshape_status {
  AIRSHAPE_OK = 0,
  AIRSHAPE_FILE_NOT_FOUND = 1,      /* the input is missing or cannot be read */
  AIRSHAPE_NOT_XML = 2,             /* not well-formed XML */
  AIRSHAPE_NOT_CPACS = 3,           /* XML, but not CPACS */
  AIRSHAPE_UNSUPPORTED_VERSION = 4, /* CPACS other than 3.x */
  AIRSHAPE_INVALID_MODEL = 5,       /* breaks a rule the geometry needs; a build failed */
  AIRSHAPE_INVALID_ARGUMENT = 6,    /* out of range, names nothing, a null pointer */
  AIRSHAPE_WRITE_FAILED = 7,        /* an output could not be written (nothing left behind) */
  AIRSHAPE_PLUGIN_FAILED = 8,       /* a plugin could not be loaded */
  AIRSHAPE_NOT_IMPLEMENTED = 9,     /* no builder yet for that component type */
  AIRSHAPE_INTERNAL_ERROR = 10      /* a bug: please report the message */
} airshape_status;

/* The message of the calling thread's last failure ("" if none); valid until its next call. */
const char* airshape_last_error(void);
/* "AIRSHAPE_OK", "AIRSHAPE_FILE_NOT_FOUND", ... */
const char* airshape_status_name(airshape_status status);
void airshape_free(char* text);

/* Opening, saving, closing. */
airshape_status airshape_open(const char* path, airshape_configuration** configuration);
airshape_status airshape_open_string(const char* xml, const char* name, airshape_configuration** configuration);
airshape_status airshape_save(airshape_configuration* configuration, const char* path);
void airshape_close(airshape_configuration* configuration);

/* Any op of the query protocol: a JSON object in ({"op": "wing_span", "wing": "W1"}), its
 * result as JSON out. */
airshape_status airshape_query(airshape_configuration* configuration, const char* query_json, char** result_json);

/* Build options that the loaded plugins declare (docs/c-api.md), all off when a file is opened:
   "duct_cutouts" cuts the duct assemblies out of the wings and fuselages they pass through.
   Turning one on or off rebuilds what it changes on next use; an unknown name is
   AIRSHAPE_INVALID_ARGUMENT. */
airshape_status airshape_set_option(airshape_configuration* configuration, const char* name, int on);
airshape_status airshape_get_option(airshape_configuration* configuration, const char* name, int* on);
/* Shorthand for airshape_set_option(configuration, "duct_cutouts", on). */
airshape_status airshape_set_duct_cutouts(airshape_configuration* configuration, int on);

/* Editing by XPath (docs/python.md#editing): what depends on the edit is rebuilt on next use. */
airshape_status airshape_get_value(airshape_configuration* configuration, const char* xpath, char** value);
airshape_status airshape_set_value(airshape_configuration* configuration, const char* xpath, const char* value);
/* Inserts XML elements under the element at parent_xpath, before its position-th child
 * element (1-based; 0 appends); removes an element. Refused edits change nothing. */
airshape_status airshape_insert_xml(airshape_configuration* configuration, const char* parent_xpath, const char* xml,
                                    int position);
airshape_status airshape_remove(airshape_configuration* configuration, const char* xpath);
airshape_status airshape_cache_statistics(airshape_configuration* configuration, size_t* built, size_t* reused,
                                          size_t* invalidated);

/* Exports by extension (docs/export.md): components is a comma-separated list of uIDs or
 * NULL for all; a deflection of 0 takes the default. */
airshape_status airshape_export(airshape_configuration* configuration, const char* path, const char* components,
                                int mirror, int fused, double linear_deflection, double angular_deflection);

/* Meshes the configuration through Gmsh (docs/meshing.md) and writes the mesh to path (.msh,
 * .su2, .vtu, .inp or .stl): options are those of `airshape mesh` separated by spaces, e.g.
 * "--farfield 20L --symmetry --size 0.5" or "--structure --order 2" (NULL or "": the surface
 * of the fused aircraft). report_json receives {"meshes": [{"name", "nodes", "elements",
 * "worst_quality", "seconds"}], "failures": [...], "notes": [...]} (free it with
 * airshape_free). AIRSHAPE_NOT_IMPLEMENTED in builds without meshing. */
airshape_status airshape_mesh(airshape_configuration* configuration, const char* path, const char* options,
                              char** report_json);

/* Any component by uID (QUERY-components): its type name, the volume of its solids (0 for
 * surfaces such as spars and ribs), the area of its faces, and the components inside it as a
 * JSON list of {"uid", "type"}. */
airshape_status airshape_component_type(airshape_configuration* configuration, const char* uid, char** type);
airshape_status airshape_component_volume(airshape_configuration* configuration, const char* uid, double* volume);
airshape_status airshape_component_surface_area(airshape_configuration* configuration, const char* uid, double* area);
airshape_status airshape_component_children(airshape_configuration* configuration, const char* uid,
                                            char** children_json);

/* Exports with control devices deflected: deflect is "UID=P,UID=P,..." with P a number, min
 * or max, UID a device or "all" (docs/controlsurfaces.md); NULL or "" exports as above. */
airshape_status airshape_export_deflected(airshape_configuration* configuration, const char* path,
                                          const char* components, const char* deflect, int mirror, int fused,
                                          double linear_deflection, double angular_deflection);

/* Writes the structural model (docs/structure.md) of the component segments (or wings) named
 * in components (comma-separated, NULL for all): skins split at spars and ribs, webs and ribs,
 * one shell sharing edges. */
airshape_status airshape_export_structure(airshape_configuration* configuration, const char* path,
                                          const char* components);

/* Writes the components named in components (comma-separated, NULL for all) with frames and
 * stringers as their structural profiles swept along their lines (docs/structure.md); a frame
 * whose profile cannot be swept is written as its line. */
airshape_status airshape_export_profiles(airshape_configuration* configuration, const char* path,
                                         const char* components);

/* Control devices of a wing (1-based index, spoilers apart) and, by uID, their control
 * parameter range and rigid motion at p: matrix is [R | t] by rows (12 numbers), rotation the
 * hinge-line rotation in degrees. */
airshape_status airshape_control_surface_count(airshape_configuration* configuration, int wing, int* count);
airshape_status airshape_control_surface_uid(airshape_configuration* configuration, int wing, int index, char** uid);
airshape_status airshape_spoiler_count(airshape_configuration* configuration, int wing, int* count);
airshape_status airshape_spoiler_uid(airshape_configuration* configuration, int wing, int index, char** uid);
airshape_status airshape_control_surface_range(airshape_configuration* configuration, const char* uid, double* minimum,
                                               double* maximum);
airshape_status airshape_control_surface_motion(airshape_configuration* configuration, const char* uid, double p,
                                                double matrix[12], double* rotation);

/* Wings. */
airshape_status airshape_wing_count(airshape_configuration* configuration, int* count);
airshape_status airshape_wing_uid(airshape_configuration* configuration, int wing, char** uid);
airshape_status airshape_wing_segment_count(airshape_configuration* configuration, int wing, int* count);
airshape_status airshape_wing_section_count(airshape_configuration* configuration, int wing, int* count);
airshape_status airshape_wing_component_segment_count(airshape_configuration* configuration, int wing, int* count);
airshape_status airshape_wing_symmetry(airshape_configuration* configuration, int wing, char** symmetry);
airshape_status airshape_wing_upper_point(airshape_configuration* configuration, int wing, int segment, double eta,
                                          double xsi, double point[3]);
airshape_status airshape_wing_lower_point(airshape_configuration* configuration, int wing, int segment, double eta,
                                          double xsi, double point[3]);
airshape_status airshape_wing_chord_point(airshape_configuration* configuration, int wing, int segment, double eta,
                                          double xsi, double point[3]);
airshape_status airshape_wing_segment_eta_xsi(airshape_configuration* configuration, int wing, const double point[3],
                                              char** segment_uid, double* eta, double* xsi, int* on_top);
airshape_status airshape_wing_volume(airshape_configuration* configuration, int wing, double* volume);
airshape_status airshape_wing_surface_area(airshape_configuration* configuration, int wing, double* area);
airshape_status airshape_wing_segment_volume(airshape_configuration* configuration, int wing, int segment,
                                             double* volume);
airshape_status airshape_wing_segment_surface_area(airshape_configuration* configuration, int wing, int segment,
                                                   double* area);
/* plane: "x-y", "x-z" or "y-z" */
airshape_status airshape_wing_reference_area(airshape_configuration* configuration, int wing, const char* plane,
                                             double* area);
airshape_status airshape_wing_wetted_area(airshape_configuration* configuration, int wing, double* area);
airshape_status airshape_wing_span(airshape_configuration* configuration, int wing, double* span);
airshape_status airshape_wing_mac(airshape_configuration* configuration, int wing, double* mac, double point[3]);
airshape_status airshape_component_segment_to_segment(airshape_configuration* configuration, int wing,
                                                      int component_segment, double eta, double xsi, char** segment_uid,
                                                      double* segment_eta, double* segment_xsi);
airshape_status airshape_segment_to_component_segment(airshape_configuration* configuration, int wing, int segment,
                                                      int component_segment, double eta, double xsi,
                                                      double* component_segment_eta, double* component_segment_xsi);

/* Fuselages. */
airshape_status airshape_fuselage_count(airshape_configuration* configuration, int* count);
airshape_status airshape_fuselage_uid(airshape_configuration* configuration, int fuselage, char** uid);
airshape_status airshape_fuselage_segment_count(airshape_configuration* configuration, int fuselage, int* count);
airshape_status airshape_fuselage_point(airshape_configuration* configuration, int fuselage, int segment, double eta,
                                        double zeta, double point[3]);
airshape_status airshape_fuselage_volume(airshape_configuration* configuration, int fuselage, double* volume);
airshape_status airshape_fuselage_surface_area(airshape_configuration* configuration, int fuselage, double* area);
airshape_status airshape_fuselage_segment_volume(airshape_configuration* configuration, int fuselage, int segment,
                                                 double* volume);
airshape_status airshape_fuselage_segment_surface_area(airshape_configuration* configuration, int fuselage, int segment,
                                                       double* area);
airshape_status airshape_fuselage_circumference(airshape_configuration* configuration, int fuselage, int segment,
                                                double eta, double* circumference);

/* Rotors of the model the queries address (a rotorcraft model's), 1-based (docs/rotor.md). */
airshape_status airshape_rotor_count(airshape_configuration* configuration, int* count);
airshape_status airshape_rotor_uid(airshape_configuration* configuration, int rotor, char** uid);
airshape_status airshape_rotor_blade_count(airshape_configuration* configuration, int rotor, int* count);
airshape_status airshape_rotor_radius(airshape_configuration* configuration, int rotor, double* radius);
airshape_status airshape_rotor_reference_area(airshape_configuration* configuration, int rotor, double* area);
airshape_status airshape_rotor_total_blade_planform_area(airshape_configuration* configuration, int rotor,
                                                         double* area);
airshape_status airshape_rotor_solidity(airshape_configuration* configuration, int rotor, double* solidity);
airshape_status airshape_rotor_tip_speed(airshape_configuration* configuration, int rotor, double* speed);
airshape_status airshape_rotor_volume(airshape_configuration* configuration, int rotor, double* volume);
airshape_status airshape_rotor_surface_area(airshape_configuration* configuration, int rotor, double* area);

/* Any component: the tight box of one (by uID), or of everything with mirrored halves (uid NULL). */
airshape_status airshape_bounding_box(airshape_configuration* configuration, const char* uid, double min[3],
                                      double max[3]);

#ifdef __cplusplus
}
#endif

#endif /* AIRSHAPE_H */
