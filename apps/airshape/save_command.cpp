#include <filesystem>
#include <iostream>

#include "airshape/error.h"
#include "airshape/plugin/plugin_host.h"
#include "commands.h"
#include "open_configuration.h"

namespace airshape::cli {

namespace {

struct SaveOptions {
  std::string input;
  std::string output;
  bool inPlace = false;
  bool force = false;
};

SaveOptions parseSaveOptions(const Arguments& arguments) {
  SaveOptions options;
  for (std::size_t i = 0; i < arguments.size(); ++i) {
    const std::string& argument = arguments[i];
    if ((argument == "-o" || argument == "--output") && i + 1 < arguments.size()) {
      options.output = arguments[++i];
    } else if (argument == "--in-place") {
      options.inPlace = true;
    } else if (argument == "--force") {
      options.force = true;
    } else if (!argument.empty() && argument[0] != '-' && options.input.empty()) {
      options.input = argument;
    } else {
      throw Error(ErrorCode::InvalidArgument, "save: unexpected argument '" + argument + "' (see airshape help save)");
    }
  }
  if (options.input.empty() || (options.output.empty() && !options.inPlace) ||
      (!options.output.empty() && options.inPlace))
    throw Error(ErrorCode::InvalidArgument, "usage: airshape save IN -o OUT | airshape save IN --in-place");
  return options;
}

bool sameFile(const std::string& a, const std::string& b) {
  std::error_code error;
  return std::filesystem::equivalent(a, b, error);
}

}  // namespace

int runSave(const Arguments& arguments, plugin::PluginHost& host) {
  const SaveOptions options = parseSaveOptions(arguments);
  const std::string output = options.inPlace ? options.input : options.output;
  if (!options.inPlace && sameFile(options.input, output))
    throw Error(ErrorCode::InvalidArgument, "refusing to overwrite the input; use --in-place to save over it",
                options.input);
  std::error_code error;
  if (!options.inPlace && !options.force && std::filesystem::exists(output, error))
    throw Error(ErrorCode::WriteFailed, "exists already; use --force to replace it", output);
  Configuration configuration = openConfiguration(options.input, host);
  configuration.save(output);
  std::cerr << "saved " << output << '\n';
  return kSuccess;
}

}  // namespace airshape::cli
