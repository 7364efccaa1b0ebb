#pragma once

#include <string>
#include <vector>

namespace airshape::cli {

/// Refuses, before anything is built, outputs in missing folders and existing files (unless
/// `force`): Error(WriteFailed) naming the output.
void refuseUnwritableOutputs(const std::vector<std::string>& outputs, bool force);

}  // namespace airshape::cli
