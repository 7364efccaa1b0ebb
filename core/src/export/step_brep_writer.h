#pragma once

#include <string>

#include "airshape/export/export_scene.h"

// A STEP writer of our own for the B-reps we build: solids whose faces lie on B-spline
// surfaces or planes, bounded by edges along B-spline curves, lines or circles. It writes the
// file OCCT's XCAF writer writes for them (AP214, an assembly of one product per component,
// face names as STEP names, metres) several times faster; anything else goes to OCCT's writer.

namespace airshape::exporting {

/// Whether writeBrepStep can write the scene: every component a solid or a compound of
/// solids, each one closed shell of faces on B-spline surfaces or planes whose edges run along
/// B-spline curves, lines or circles (or are degenerate), placed without mirroring.
bool brepStepWritable(const ExportScene& scene);

/// Writes such a scene as STEP AP214 to `path`; throws Error(WriteFailed) naming `target`.
void writeBrepStep(const ExportScene& scene, const std::string& path, const std::string& target);

}  // namespace airshape::exporting
