// The compiled part of the Python package `airshape` (_airshape): a configuration with its
// query ops, editing, saving and exporting. The pythonic objects (wings, fuselages, the
// editing proxies) are in airshape/__init__.py on top of it.
#include <map>
#include <mutex>
#include <sstream>

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/export/exporter.h"
#ifdef AIRSHAPE_HAS_MESHING
#include "airshape/meshing/mesher.h"
#endif
#include "airshape/plugin/plugin_host.h"
#include "airshape/query/op_signature.h"
#include "airshape/query/query_registry.h"

namespace py = pybind11;
using airshape::Configuration;
using airshape::query::Json;

namespace {

airshape::plugin::PluginHost& host() { return airshape::plugin::processPlugins(); }

/// A configuration opened for Python: the configuration and a lock, since Python threads
/// may share one object.
struct PyConfiguration {
  explicit PyConfiguration(Configuration opened) : configuration(std::move(opened)) {
    configuration.useShapes(host().shapes());
  }
  Configuration configuration;
  std::mutex lock;
};

std::unique_ptr<PyConfiguration> openFile(const std::string& path) {
  return std::make_unique<PyConfiguration>(Configuration::open(path, host().componentLocations()));
}

std::unique_ptr<PyConfiguration> openString(const std::string& xml, const std::string& name) {
  return std::make_unique<PyConfiguration>(Configuration::fromString(xml, name, host().componentLocations()));
}

/// Runs one op with a JSON object of arguments (a dict from Python).
Json runOp(PyConfiguration& self, const std::string& op, Json arguments) {
  const airshape::query::Op* handler = host().queries().find(op);
  if (handler == nullptr) throw airshape::Error(airshape::ErrorCode::InvalidArgument, "unknown op '" + op + "'");
  arguments["op"] = op;
  const std::lock_guard<std::mutex> guard(self.lock);
  return handler->handler(self.configuration, arguments);
}

Json toJson(const py::handle& value) {
  return Json::parse(py::str(py::module_::import("json").attr("dumps")(value)).cast<std::string>());
}

py::object fromJson(const Json& value) { return py::module_::import("json").attr("loads")(value.dump()); }

/// One op over arrays of parameters: `arguments` holds the fixed ones, `first` and `second`
/// name the varying ones (eta and xsi, say); returns an (n, 3) array of points.
py::array_t<double> pointsOf(PyConfiguration& self, const std::string& op, const py::dict& arguments,
                             const std::string& first, py::array_t<double> firstValues, const std::string& second,
                             py::array_t<double> secondValues) {
  const auto a = firstValues.unchecked<1>();
  const auto b = secondValues.unchecked<1>();
  if (a.shape(0) != b.shape(0))
    throw airshape::Error(airshape::ErrorCode::InvalidArgument, first + " and " + second + " differ in length");
  const airshape::query::Op* handler = host().queries().find(op);
  if (handler == nullptr) throw airshape::Error(airshape::ErrorCode::InvalidArgument, "unknown op '" + op + "'");
  Json query = toJson(arguments);
  query["op"] = op;
  py::array_t<double> result({static_cast<py::ssize_t>(a.shape(0)), static_cast<py::ssize_t>(3)});
  auto out = result.mutable_unchecked<2>();
  py::gil_scoped_release release;
  const std::lock_guard<std::mutex> guard(self.lock);
  for (py::ssize_t i = 0; i < a.shape(0); ++i) {
    query[first] = a(i);
    query[second] = b(i);
    const Json point = handler->handler(self.configuration, query);
    for (int k = 0; k < 3; ++k) out(i, k) = point[static_cast<std::size_t>(k)].get<double>();
  }
  return result;
}

py::dict cacheStatistics(PyConfiguration& self) {
  const airshape::CacheStatistics statistics = self.configuration.cache().statistics();
  py::dict result;
  result["built"] = statistics.built;
  result["reused"] = statistics.reused;
  result["invalidated"] = statistics.invalidated;
  result["builds_by_key"] = statistics.buildsByKey;
  return result;
}

void exportTo(PyConfiguration& self, const std::string& path, const std::vector<std::string>& components, bool mirror,
              bool fused, double linearDeflection, double angularDeflection, const std::string& poses, bool structure,
              bool profiles) {
  airshape::exporting::ExportOptions options;
  options.poses = airshape::exporting::parsePoses(poses);
  options.structure = structure;
  options.profiles = profiles;
  options.components = components;
  options.mirror = mirror;
  options.fused = fused;
  options.linearDeflection = linearDeflection;
  if (angularDeflection > 0) options.angularDeflection = angularDeflection;
  py::gil_scoped_release release;
  const std::lock_guard<std::mutex> guard(self.lock);
  airshape::exporting::exportConfiguration(self.configuration, path, options);
}

/// Meshes into `path` with the options of `airshape mesh` (docs/meshing.md); the report as JSON.
std::string meshTo(PyConfiguration& self, const std::string& path, std::vector<std::string> arguments) {
#ifdef AIRSHAPE_HAS_MESHING
  const airshape::meshing::MeshOptions options = airshape::meshing::takeMeshOptions(arguments);
  if (!arguments.empty())
    throw airshape::Error(airshape::ErrorCode::InvalidArgument, "mesh: unexpected option '" + arguments[0] + "'");
  py::gil_scoped_release release;
  const std::lock_guard<std::mutex> guard(self.lock);
  return airshape::meshing::reportAsJson(airshape::meshing::meshConfiguration(self.configuration, {path}, options));
#else
  (void)self, (void)path, (void)arguments;
  throw airshape::Error(airshape::ErrorCode::NotImplemented,
                        "this build has no meshing: build it with Gmsh (docs/meshing.md)");
#endif
}

/// airshape::Error becomes the Python exception of its code (airshape/errors.py), with the
/// file and the CPACS path as attributes.
void translateErrors() {
  py::register_exception_translator([](std::exception_ptr pointer) {
    try {
      if (pointer) std::rethrow_exception(pointer);
    } catch (const airshape::Error& error) {
      static const char* classes[] = {"FileError",     "FileError",  "FileError",   "FileError",       "ModelError",
                                      "ArgumentError", "WriteError", "PluginError", "NotBuiltYetError"};
      const py::object errors = py::module_::import("airshape.errors");
      const py::object type = errors.attr(classes[static_cast<int>(error.code())]);
      const py::object instance = type(error.what(), error.file(), error.cpacsPath());
      PyErr_SetObject(type.ptr(), instance.ptr());
    }
  });
}

}  // namespace

PYBIND11_MODULE(_airshape, m) {
  m.doc() = "Airshape's compiled core: CPACS configurations, their query ops, editing and exports.";
  translateErrors();
  m.def(
      "ops_description", [] { return airshape::query::describeOps(host().queries()).dump(); },
      "Every query op of the loaded plugins with its owner, summary, arguments and answer, as JSON.");
  py::class_<PyConfiguration>(m, "Configuration", "A CPACS 3 file opened for geometry.")
      .def_static("open", &openFile, py::arg("path"), "Opens a CPACS 3 file.")
      .def_static("from_string", &openString, py::arg("xml"), py::arg("name") = "<string>",
                  "Opens a CPACS 3 document held in a string; `name` stands for it in messages.")
      .def_property_readonly(
          "source", [](PyConfiguration& self) { return self.configuration.source(); }, "The file it was read from.")
      .def(
          "query",
          [](PyConfiguration& self, const std::string& op, const py::dict& arguments) {
            return fromJson(runOp(self, op, toJson(arguments)));
          },
          py::arg("op"), py::arg("arguments") = py::dict(),
          "Runs one op of the query protocol (docs/query.md) with a dict of arguments.")
      .def("points", &pointsOf, py::arg("op"), py::arg("arguments"), py::arg("first"), py::arg("first_values"),
           py::arg("second"), py::arg("second_values"),
           "Runs a point op for arrays of two parameters; returns an (n, 3) array.")
      .def(
          "value",
          [](PyConfiguration& self, const std::string& xpath) {
            const std::lock_guard<std::mutex> guard(self.lock);
            return self.configuration.value(xpath);
          },
          py::arg("xpath"), "The text (or attribute value) an XPath addresses.")
      .def(
          "set",
          [](PyConfiguration& self, const std::string& xpath, const std::string& value) {
            const std::lock_guard<std::mutex> guard(self.lock);
            self.configuration.setValue(xpath, value);
          },
          py::arg("xpath"), py::arg("value"), "Sets a value by XPath; what depends on it is rebuilt on next use.")
      .def(
          "xml",
          [](PyConfiguration& self, const std::string& xpath) {
            const std::lock_guard<std::mutex> guard(self.lock);
            return self.configuration.xmlOf(xpath);
          },
          py::arg("xpath"), "The element at an XPath with all it holds, as XML text.")
      .def(
          "insert",
          [](PyConfiguration& self, const std::string& parent, const std::string& xml, std::size_t position) {
            const std::lock_guard<std::mutex> guard(self.lock);
            self.configuration.insertXml(parent, xml, position);
          },
          py::arg("parent"), py::arg("xml"), py::arg("position") = 0,
          "Inserts XML elements under the element at `parent`, before its position-th child (1-based; 0 appends).")
      .def(
          "remove",
          [](PyConfiguration& self, const std::string& xpath) {
            const std::lock_guard<std::mutex> guard(self.lock);
            self.configuration.remove(xpath);
          },
          py::arg("xpath"), "Removes the element at an XPath with all it holds.")
      .def(
          "count",
          [](PyConfiguration& self, const std::string& xpath) {
            const std::lock_guard<std::mutex> guard(self.lock);
            std::size_t count = 0;
            while (true) {
              try {
                self.configuration.value(xpath + "[" + std::to_string(count + 1) + "]");
              } catch (const airshape::Error&) {
                return count;
              }
              ++count;
            }
          },
          py::arg("xpath"), "How many elements the XPath's last step names under its parent.")
      .def(
          "save",
          [](PyConfiguration& self, const std::string& path) {
            const std::lock_guard<std::mutex> guard(self.lock);
            self.configuration.save(path);
          },
          py::arg("path"), "Writes the document (edits included), safely.")
      .def("export", &exportTo, py::arg("path"), py::arg("components") = std::vector<std::string>(),
           py::arg("mirror") = false, py::arg("fused") = false, py::arg("linear_deflection") = 0.0,
           py::arg("angular_deflection") = 0.0, py::arg("poses") = std::string(), py::arg("structure") = false,
           py::arg("profiles") = false,
           "Writes STEP, IGES, BREP, STL, VTP, glTF/GLB or OBJ by extension; poses: UID=P,... devices deflected; "
           "profiles: frames and stringers with their structural profiles swept along them.")
      .def("mesh", &meshTo, py::arg("path"), py::arg("arguments"),
           "Meshes through Gmsh into path with the options of `airshape mesh`; returns the report as JSON.")
      .def(
          "set_option",
          [](PyConfiguration& self, const std::string& name, bool on) {
            const std::lock_guard<std::mutex> guard(self.lock);
            self.configuration.setOption(name, on);
          },
          py::arg("name"), py::arg("on"),
          "Turns a build option the plugins declare on or off (duct_cutouts); what it changes is rebuilt.")
      .def(
          "option", [](PyConfiguration& self, const std::string& name) { return self.configuration.option(name); },
          py::arg("name"), "Whether a build option is on.")
      .def(
          "options",
          [](PyConfiguration& self) {
            std::map<std::string, std::string> declared;
            for (const airshape::ComponentCutOuts& cutOuts : self.configuration.shapes().cutOuts())
              declared[cutOuts.option] = cutOuts.description;
            return declared;
          },
          "The build options the loaded plugins declare, each with its description.")
      .def("cache_statistics", &cacheStatistics, "Objects built, reused and invalidated, and builds per key.");
}
