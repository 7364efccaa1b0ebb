#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Geom_BSplineSurface.hxx>
#include <TopoDS_Face.hxx>

#include "airshape/named_shape.h"
#include "airshape/schema/generated/cpacs_model.h"
#include "airshape/wing/wing_services.h"

namespace airshape {
class Configuration;
}

namespace airshape::nacelle {

/// An engine pylon (QUERY-components §1, `engine_pylon`; docs/nacelle.md): a wing-like body of
/// sections (wing airfoils placed by element, section, positioning and the pylon's own
/// transformation with its parent's translation) and segments, lofted smoothly through the
/// airfoils of its segment chain as the reference library lofts pylons: each edge of the
/// airfoil outlines (one curve, or lower and upper side, and a blunt trailing edge) skinned
/// across the sections at the centripetal section parameters of the first edge, degree up to
/// 3 along the span; closed by plane caps at the first and the last section.
class PylonLoft {
 public:
  /// Builds (or takes from the configuration's cache) the loft of the pylon of this uID.
  /// Throws Error naming the CPACS path of what cannot be built.
  static std::shared_ptr<const PylonLoft> of(const Configuration& configuration, const wing::WingServices& wing,
                                             const std::string& pylonUid);

  /// The pylon's solid: faces "<uID>/skin", "<uID>/inner cap", "<uID>/outer cap".
  NamedShape solid() const;
  /// The solid of one segment (by uID): the loft between its two sections, capped.
  NamedShape segmentSolid(const std::string& segmentUid) const;

  const std::vector<std::string>& segmentUids() const { return segmentUids_; }

 private:
  NamedShape piece(std::size_t from, std::size_t to, const std::string& name) const;

  std::string uid_, xpath_;
  std::vector<std::string> segmentUids_;
  std::vector<Handle(Geom_BSplineSurface)> skins_;  ///< one per outline edge
  std::vector<TopoDS_Face> caps_;                   ///< the plane face of each section's outline
  std::vector<double> parameters_;                  ///< where the skins pass each section
};

/// The pylon (any model) holding this pylon segment uID, or empty.
std::string pylonHoldingSegment(const Configuration& configuration, const std::string& segmentUid);

}  // namespace airshape::nacelle
