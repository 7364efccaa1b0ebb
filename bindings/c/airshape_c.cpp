// The C interface (airshape.h) over the C++ library: each function runs its body inside
// guarded(), which turns every exception into a status and the thread's last-error message.
#include <cstdlib>
#include <cstring>
#include <mutex>
#include <new>
#include <sstream>
#include <string>
#include <vector>

#include <Standard_Failure.hxx>

#include "airshape.h"
#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/export/exporter.h"
#ifdef AIRSHAPE_HAS_MESHING
#include "airshape/meshing/mesher.h"
#endif
#include "airshape/plugin/plugin_host.h"
#include "airshape/query/query_registry.h"

using airshape::Error;
using airshape::ErrorCode;
using airshape::query::Json;

struct airshape_configuration {
  explicit airshape_configuration(airshape::Configuration opened) : configuration(std::move(opened)) {}
  airshape::Configuration configuration;
  std::mutex lock;  // one call at a time per handle
};

namespace {

thread_local std::string lastError;

airshape::plugin::PluginHost& host() { return airshape::plugin::processPlugins(); }

template <class Body>
airshape_status guarded(Body&& body) {
  try {
    body();
    lastError.clear();
    return AIRSHAPE_OK;
  } catch (const Error& error) {
    lastError = error.what();
    return static_cast<airshape_status>(static_cast<int>(error.code()) + 1);
  } catch (const Standard_Failure& failure) {
    lastError = std::string("geometry kernel failure: ") + failure.GetMessageString();
    return AIRSHAPE_INVALID_MODEL;
  } catch (const std::bad_alloc&) {
    lastError = "out of memory";
  } catch (const std::exception& error) {
    lastError = std::string("internal error: ") + error.what();
  } catch (...) {
    lastError = "internal error: unknown exception";
  }
  return AIRSHAPE_INTERNAL_ERROR;
}

void require(const void* pointer, const char* name) {
  if (pointer == nullptr) throw Error(ErrorCode::InvalidArgument, std::string(name) + " is NULL");
}

/// Runs an op on a configuration under its lock.
Json run(airshape_configuration* configuration, const char* op, Json arguments) {
  require(configuration, "configuration");
  const airshape::query::Op* handler = host().queries().find(op);
  if (handler == nullptr) throw Error(ErrorCode::NotImplemented, std::string("no plugin answers ") + op);
  arguments["op"] = op;
  const std::lock_guard<std::mutex> guard(configuration->lock);
  return handler->handler(configuration->configuration, arguments);
}

char* copied(const std::string& text) {
  char* copy = static_cast<char*>(std::malloc(text.size() + 1));
  if (copy == nullptr) throw std::bad_alloc();
  std::memcpy(copy, text.c_str(), text.size() + 1);
  return copy;
}

void toPoint(const Json& value, double point[3]) {
  for (std::size_t k = 0; k < 3; ++k) point[k] = value.at(k).get<double>();
}

airshape_status count(airshape_configuration* c, const char* op, Json arguments, int* result) {
  return guarded([&] {
    require(result, "count");
    *result = run(c, op, std::move(arguments)).get<int>();
  });
}

airshape_status number(airshape_configuration* c, const char* op, Json arguments, double* result) {
  return guarded([&] {
    require(result, "result");
    *result = run(c, op, std::move(arguments)).get<double>();
  });
}

airshape_status text(airshape_configuration* c, const char* op, Json arguments, char** result) {
  return guarded([&] {
    require(result, "result");
    *result = copied(run(c, op, std::move(arguments)).get<std::string>());
  });
}

airshape_status point(airshape_configuration* c, const char* op, Json arguments, double result[3]) {
  return guarded([&] {
    require(result, "point");
    toPoint(run(c, op, std::move(arguments)), result);
  });
}

airshape_status opened(airshape_configuration** configuration, airshape::Configuration&& loaded) {
  *configuration = new airshape_configuration(std::move(loaded));
  (*configuration)->configuration.useShapes(host().shapes());
  return AIRSHAPE_OK;
}

/// Writes the components named (comma-separated, NULL for all) with one export option set: the
/// structural model, or frames and stringers with their profiles.
airshape_status exportWith(airshape_configuration* configuration, const char* path, const char* components,
                           bool airshape::exporting::ExportOptions::*option) {
  return guarded([&] {
    require(configuration, "configuration");
    require(path, "path");
    airshape::exporting::ExportOptions options;
    if (components != nullptr) options.components = airshape::exporting::splitAtCommas(components);
    options.*option = true;
    const std::lock_guard<std::mutex> guard(configuration->lock);
    airshape::exporting::exportConfiguration(configuration->configuration, path, options);
  });
}

}  // namespace

extern "C" {

const char* airshape_last_error(void) { return lastError.c_str(); }

const char* airshape_status_name(airshape_status status) {
  static const char* names[] = {"AIRSHAPE_OK",
                                "AIRSHAPE_FILE_NOT_FOUND",
                                "AIRSHAPE_NOT_XML",
                                "AIRSHAPE_NOT_CPACS",
                                "AIRSHAPE_UNSUPPORTED_VERSION",
                                "AIRSHAPE_INVALID_MODEL",
                                "AIRSHAPE_INVALID_ARGUMENT",
                                "AIRSHAPE_WRITE_FAILED",
                                "AIRSHAPE_PLUGIN_FAILED",
                                "AIRSHAPE_NOT_IMPLEMENTED",
                                "AIRSHAPE_INTERNAL_ERROR"};
  const int index = static_cast<int>(status);
  return index >= 0 && index <= AIRSHAPE_INTERNAL_ERROR ? names[index] : "AIRSHAPE_UNKNOWN_STATUS";
}

void airshape_free(char* text) { std::free(text); }

airshape_status airshape_open(const char* path, airshape_configuration** configuration) {
  return guarded([&] {
    require(path, "path");
    require(configuration, "configuration");
    *configuration = nullptr;
    opened(configuration, airshape::Configuration::open(path, host().componentLocations()));
  });
}

airshape_status airshape_open_string(const char* xml, const char* name, airshape_configuration** configuration) {
  return guarded([&] {
    require(xml, "xml");
    require(configuration, "configuration");
    *configuration = nullptr;
    opened(configuration,
           airshape::Configuration::fromString(xml, name ? name : "<string>", host().componentLocations()));
  });
}

airshape_status airshape_save(airshape_configuration* configuration, const char* path) {
  return guarded([&] {
    require(configuration, "configuration");
    require(path, "path");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    configuration->configuration.save(path);
  });
}

void airshape_close(airshape_configuration* configuration) { delete configuration; }

airshape_status airshape_query(airshape_configuration* configuration, const char* query_json, char** result_json) {
  return guarded([&] {
    require(query_json, "query_json");
    require(result_json, "result_json");
    const Json query = Json::parse(query_json, nullptr, false);
    if (!query.is_object() || !query.contains("op") || !query.at("op").is_string())
      throw Error(ErrorCode::InvalidArgument, "the query must be a JSON object with an \"op\" string");
    *result_json = copied(run(configuration, query.at("op").get<std::string>().c_str(), query).dump());
  });
}

airshape_status airshape_get_value(airshape_configuration* configuration, const char* xpath, char** value) {
  return guarded([&] {
    require(configuration, "configuration");
    require(xpath, "xpath");
    require(value, "value");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    *value = copied(configuration->configuration.value(xpath));
  });
}

airshape_status airshape_set_value(airshape_configuration* configuration, const char* xpath, const char* value) {
  return guarded([&] {
    require(configuration, "configuration");
    require(xpath, "xpath");
    require(value, "value");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    configuration->configuration.setValue(xpath, value);
  });
}

airshape_status airshape_set_option(airshape_configuration* configuration, const char* name, int on) {
  return guarded([&] {
    require(configuration, "configuration");
    require(name, "name");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    configuration->configuration.setOption(name, on != 0);
  });
}

airshape_status airshape_get_option(airshape_configuration* configuration, const char* name, int* on) {
  return guarded([&] {
    require(configuration, "configuration");
    require(name, "name");
    require(on, "on");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    bool declared = false;
    for (const airshape::ComponentCutOuts& cutOuts : configuration->configuration.shapes().cutOuts())
      declared = declared || cutOuts.option == name;
    if (!declared) throw Error(ErrorCode::InvalidArgument, std::string("no build option '") + name + "'");
    *on = configuration->configuration.option(name) ? 1 : 0;
  });
}

airshape_status airshape_set_duct_cutouts(airshape_configuration* configuration, int on) {
  return airshape_set_option(configuration, "duct_cutouts", on);
}

airshape_status airshape_insert_xml(airshape_configuration* configuration, const char* parent_xpath, const char* xml,
                                    int position) {
  return guarded([&] {
    require(configuration, "configuration");
    require(parent_xpath, "parent_xpath");
    require(xml, "xml");
    if (position < 0) throw Error(ErrorCode::InvalidArgument, "position must not be negative");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    configuration->configuration.insertXml(parent_xpath, xml, static_cast<std::size_t>(position));
  });
}

airshape_status airshape_remove(airshape_configuration* configuration, const char* xpath) {
  return guarded([&] {
    require(configuration, "configuration");
    require(xpath, "xpath");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    configuration->configuration.remove(xpath);
  });
}

airshape_status airshape_cache_statistics(airshape_configuration* configuration, size_t* built, size_t* reused,
                                          size_t* invalidated) {
  return guarded([&] {
    require(configuration, "configuration");
    const airshape::CacheStatistics statistics = configuration->configuration.cache().statistics();
    if (built) *built = statistics.built;
    if (reused) *reused = statistics.reused;
    if (invalidated) *invalidated = statistics.invalidated;
  });
}

airshape_status airshape_export_deflected(airshape_configuration* configuration, const char* path,
                                          const char* components, const char* deflect, int mirror, int fused,
                                          double linear_deflection, double angular_deflection) {
  return guarded([&] {
    require(configuration, "configuration");
    require(path, "path");
    airshape::exporting::ExportOptions options;
    if (components != nullptr) options.components = airshape::exporting::splitAtCommas(components);
    if (deflect != nullptr) options.poses = airshape::exporting::parsePoses(deflect);
    options.mirror = mirror != 0;
    options.fused = fused != 0;
    options.linearDeflection = linear_deflection;
    if (angular_deflection > 0) options.angularDeflection = angular_deflection;
    const std::lock_guard<std::mutex> guard(configuration->lock);
    airshape::exporting::exportConfiguration(configuration->configuration, path, options);
  });
}

airshape_status airshape_export_structure(airshape_configuration* configuration, const char* path,
                                          const char* components) {
  return exportWith(configuration, path, components, &airshape::exporting::ExportOptions::structure);
}

airshape_status airshape_export_profiles(airshape_configuration* configuration, const char* path,
                                         const char* components) {
  return exportWith(configuration, path, components, &airshape::exporting::ExportOptions::profiles);
}

airshape_status airshape_mesh(airshape_configuration* configuration, const char* path, const char* options,
                              char** report_json) {
  return guarded([&] {
    require(configuration, "configuration");
    require(path, "path");
    require(report_json, "report_json");
#ifdef AIRSHAPE_HAS_MESHING
    std::vector<std::string> arguments;
    std::istringstream words(options == nullptr ? "" : options);
    for (std::string word; words >> word;) arguments.push_back(word);
    const airshape::meshing::MeshOptions meshOptions = airshape::meshing::takeMeshOptions(arguments);
    if (!arguments.empty()) throw Error(ErrorCode::InvalidArgument, "mesh: unexpected option '" + arguments[0] + "'");
    const std::lock_guard<std::mutex> guard(configuration->lock);
    *report_json = copied(airshape::meshing::reportAsJson(
        airshape::meshing::meshConfiguration(configuration->configuration, {path}, meshOptions)));
#else
    throw Error(ErrorCode::NotImplemented, "this build has no meshing: build it with Gmsh (docs/meshing.md)");
#endif
  });
}

airshape_status airshape_export(airshape_configuration* configuration, const char* path, const char* components,
                                int mirror, int fused, double linear_deflection, double angular_deflection) {
  return airshape_export_deflected(configuration, path, components, nullptr, mirror, fused, linear_deflection,
                                   angular_deflection);
}

airshape_status airshape_component_type(airshape_configuration* c, const char* uid, char** type) {
  return guarded([&] {
    require(uid, "uid");
    require(type, "type");
    *type = copied(run(c, "component_type", {{"uid", uid}}).get<std::string>());
  });
}
airshape_status airshape_component_volume(airshape_configuration* c, const char* uid, double* volume) {
  return guarded([&] {
    require(uid, "uid");
    require(volume, "volume");
    *volume = run(c, "component_volume", {{"uid", uid}}).get<double>();
  });
}
airshape_status airshape_component_surface_area(airshape_configuration* c, const char* uid, double* area) {
  return guarded([&] {
    require(uid, "uid");
    require(area, "area");
    *area = run(c, "component_surface_area", {{"uid", uid}}).get<double>();
  });
}
airshape_status airshape_component_children(airshape_configuration* c, const char* uid, char** children) {
  return guarded([&] {
    require(uid, "uid");
    require(children, "children");
    *children = copied(run(c, "component_children", {{"uid", uid}}).dump());
  });
}

airshape_status airshape_control_surface_count(airshape_configuration* c, int wing, int* result) {
  return count(c, "control_surface_count", {{"wing", wing}}, result);
}
airshape_status airshape_control_surface_uid(airshape_configuration* c, int wing, int index, char** uid) {
  return text(c, "control_surface_uid", {{"wing", wing}, {"index", index}}, uid);
}
airshape_status airshape_spoiler_count(airshape_configuration* c, int wing, int* result) {
  return count(c, "spoiler_count", {{"wing", wing}}, result);
}
airshape_status airshape_spoiler_uid(airshape_configuration* c, int wing, int index, char** uid) {
  return text(c, "spoiler_uid", {{"wing", wing}, {"index", index}}, uid);
}
airshape_status airshape_control_surface_range(airshape_configuration* c, const char* uid, double* minimum,
                                               double* maximum) {
  return guarded([&] {
    require(uid, "uid");
    const Json found = run(c, "control_surface_parameter_range", {{"uid", uid}});
    if (minimum) *minimum = found.at("min").get<double>();
    if (maximum) *maximum = found.at("max").get<double>();
  });
}
airshape_status airshape_control_surface_motion(airshape_configuration* c, const char* uid, double p, double matrix[12],
                                                double* rotation) {
  return guarded([&] {
    require(uid, "uid");
    const Json found = run(c, "control_surface_deflection", {{"uid", uid}, {"control_parameter", p}});
    if (matrix)
      for (std::size_t row = 0; row < 3; ++row)
        for (std::size_t column = 0; column < 4; ++column)
          matrix[4 * row + column] = found.at("matrix").at(row).at(column).get<double>();
    if (rotation) *rotation = found.at("rotation").get<double>();
  });
}

/* Wings. */
airshape_status airshape_wing_count(airshape_configuration* c, int* result) {
  return count(c, "wing_count", Json::object(), result);
}
airshape_status airshape_wing_uid(airshape_configuration* c, int wing, char** uid) {
  return text(c, "wing_uid", {{"wing", wing}}, uid);
}
airshape_status airshape_wing_segment_count(airshape_configuration* c, int wing, int* result) {
  return count(c, "wing_segment_count", {{"wing", wing}}, result);
}
airshape_status airshape_wing_section_count(airshape_configuration* c, int wing, int* result) {
  return count(c, "wing_section_count", {{"wing", wing}}, result);
}
airshape_status airshape_wing_component_segment_count(airshape_configuration* c, int wing, int* result) {
  return count(c, "wing_component_segment_count", {{"wing", wing}}, result);
}
airshape_status airshape_wing_symmetry(airshape_configuration* c, int wing, char** symmetry) {
  return text(c, "wing_symmetry", {{"wing", wing}}, symmetry);
}
airshape_status airshape_wing_upper_point(airshape_configuration* c, int wing, int segment, double eta, double xsi,
                                          double result[3]) {
  return point(c, "wing_upper_point", {{"wing", wing}, {"segment", segment}, {"eta", eta}, {"xsi", xsi}}, result);
}
airshape_status airshape_wing_lower_point(airshape_configuration* c, int wing, int segment, double eta, double xsi,
                                          double result[3]) {
  return point(c, "wing_lower_point", {{"wing", wing}, {"segment", segment}, {"eta", eta}, {"xsi", xsi}}, result);
}
airshape_status airshape_wing_chord_point(airshape_configuration* c, int wing, int segment, double eta, double xsi,
                                          double result[3]) {
  return point(c, "wing_chord_point", {{"wing", wing}, {"segment", segment}, {"eta", eta}, {"xsi", xsi}}, result);
}
airshape_status airshape_wing_segment_eta_xsi(airshape_configuration* c, int wing, const double p[3],
                                              char** segment_uid, double* eta, double* xsi, int* on_top) {
  return guarded([&] {
    require(p, "point");
    const Json found = run(c, "wing_segment_eta_xsi", {{"wing", wing}, {"x", p[0]}, {"y", p[1]}, {"z", p[2]}});
    if (segment_uid) *segment_uid = copied(found.at("segment").get<std::string>());
    if (eta) *eta = found.at("eta").get<double>();
    if (xsi) *xsi = found.at("xsi").get<double>();
    if (on_top) *on_top = found.at("on_top").get<bool>() ? 1 : 0;
  });
}
airshape_status airshape_wing_volume(airshape_configuration* c, int wing, double* result) {
  return number(c, "wing_volume", {{"wing", wing}}, result);
}
airshape_status airshape_wing_surface_area(airshape_configuration* c, int wing, double* result) {
  return number(c, "wing_surface_area", {{"wing", wing}}, result);
}
airshape_status airshape_wing_segment_volume(airshape_configuration* c, int wing, int segment, double* result) {
  return number(c, "wing_segment_volume", {{"wing", wing}, {"segment", segment}}, result);
}
airshape_status airshape_wing_segment_surface_area(airshape_configuration* c, int wing, int segment, double* result) {
  return number(c, "wing_segment_surface_area", {{"wing", wing}, {"segment", segment}}, result);
}
airshape_status airshape_wing_reference_area(airshape_configuration* c, int wing, const char* plane, double* result) {
  return number(c, "wing_reference_area", {{"wing", wing}, {"plane", plane ? plane : "x-y"}}, result);
}
airshape_status airshape_wing_wetted_area(airshape_configuration* c, int wing, double* result) {
  return number(c, "wing_wetted_area", {{"wing", wing}}, result);
}
airshape_status airshape_wing_span(airshape_configuration* c, int wing, double* result) {
  return number(c, "wing_span", {{"wing", wing}}, result);
}
airshape_status airshape_wing_mac(airshape_configuration* c, int wing, double* mac, double p[3]) {
  return guarded([&] {
    const Json found = run(c, "wing_mac", {{"wing", wing}});
    if (mac) *mac = found.at("mac").get<double>();
    if (p) toPoint(found.at("point"), p);
  });
}
airshape_status airshape_component_segment_to_segment(airshape_configuration* c, int wing, int component_segment,
                                                      double eta, double xsi, char** segment_uid, double* segment_eta,
                                                      double* segment_xsi) {
  return guarded([&] {
    const Json found = run(c, "component_segment_to_segment",
                           {{"wing", wing}, {"component_segment", component_segment}, {"eta", eta}, {"xsi", xsi}});
    if (segment_uid) *segment_uid = copied(found.at("segment").get<std::string>());
    if (segment_eta) *segment_eta = found.at("eta").get<double>();
    if (segment_xsi) *segment_xsi = found.at("xsi").get<double>();
  });
}
airshape_status airshape_segment_to_component_segment(airshape_configuration* c, int wing, int segment,
                                                      int component_segment, double eta, double xsi,
                                                      double* component_segment_eta, double* component_segment_xsi) {
  return guarded([&] {
    const Json found = run(
        c, "segment_to_component_segment",
        {{"wing", wing}, {"segment", segment}, {"component_segment", component_segment}, {"eta", eta}, {"xsi", xsi}});
    if (component_segment_eta) *component_segment_eta = found.at("eta").get<double>();
    if (component_segment_xsi) *component_segment_xsi = found.at("xsi").get<double>();
  });
}

airshape_status airshape_rotor_count(airshape_configuration* c, int* result) {
  return count(c, "rotor_count", Json::object(), result);
}
airshape_status airshape_rotor_uid(airshape_configuration* c, int rotor, char** uid) {
  return text(c, "rotor_uid", {{"rotor", rotor}}, uid);
}
airshape_status airshape_rotor_blade_count(airshape_configuration* c, int rotor, int* result) {
  return count(c, "rotor_blade_count", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_radius(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_radius", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_reference_area(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_reference_area", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_total_blade_planform_area(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_total_blade_planform_area", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_solidity(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_solidity", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_tip_speed(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_tip_speed", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_volume(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_volume", {{"rotor", rotor}}, result);
}
airshape_status airshape_rotor_surface_area(airshape_configuration* c, int rotor, double* result) {
  return number(c, "rotor_surface_area", {{"rotor", rotor}}, result);
}
airshape_status airshape_fuselage_count(airshape_configuration* c, int* result) {
  return count(c, "fuselage_count", Json::object(), result);
}
airshape_status airshape_fuselage_uid(airshape_configuration* c, int fuselage, char** uid) {
  return text(c, "fuselage_uid", {{"fuselage", fuselage}}, uid);
}
airshape_status airshape_fuselage_segment_count(airshape_configuration* c, int fuselage, int* result) {
  return count(c, "fuselage_segment_count", {{"fuselage", fuselage}}, result);
}
airshape_status airshape_fuselage_point(airshape_configuration* c, int fuselage, int segment, double eta, double zeta,
                                        double result[3]) {
  return point(c, "fuselage_point", {{"fuselage", fuselage}, {"segment", segment}, {"eta", eta}, {"zeta", zeta}},
               result);
}
airshape_status airshape_fuselage_volume(airshape_configuration* c, int fuselage, double* result) {
  return number(c, "fuselage_volume", {{"fuselage", fuselage}}, result);
}
airshape_status airshape_fuselage_surface_area(airshape_configuration* c, int fuselage, double* result) {
  return number(c, "fuselage_surface_area", {{"fuselage", fuselage}}, result);
}
airshape_status airshape_fuselage_segment_volume(airshape_configuration* c, int fuselage, int segment, double* result) {
  return number(c, "fuselage_segment_volume", {{"fuselage", fuselage}, {"segment", segment}}, result);
}
airshape_status airshape_fuselage_segment_surface_area(airshape_configuration* c, int fuselage, int segment,
                                                       double* result) {
  return number(c, "fuselage_segment_surface_area", {{"fuselage", fuselage}, {"segment", segment}}, result);
}
airshape_status airshape_fuselage_circumference(airshape_configuration* c, int fuselage, int segment, double eta,
                                                double* result) {
  return number(c, "fuselage_circumference", {{"fuselage", fuselage}, {"segment", segment}, {"eta", eta}}, result);
}

airshape_status airshape_bounding_box(airshape_configuration* c, const char* uid, double min[3], double max[3]) {
  return guarded([&] {
    require(min, "min");
    require(max, "max");
    Json arguments = Json::object();
    if (uid != nullptr) arguments["uid"] = uid;
    const Json box = run(c, "bounding_box", arguments);
    toPoint(box.at("min"), min);
    toPoint(box.at("max"), max);
  });
}

}  // extern "C"
