#include "airshape/model/symmetry.h"

#include <gp_Ax2.hxx>
#include <xercesc/dom/DOM.hpp>

#include "airshape/configuration.h"
#include "airshape/xml/text.h"

namespace airshape::model {

std::string resolvedSymmetry(const Configuration& configuration, const std::string& componentUid) {
  const graph::ComponentGraph& graph = configuration.components();
  std::string uid = componentUid;
  // A parentUID chain is acyclic (the graph refuses cycles), so this walk ends.
  for (std::size_t steps = 0; steps <= graph.components().size(); ++steps) {
    const long index = graph.find(uid);
    if (index < 0) return "none";
    const graph::Component& component = graph.components()[static_cast<std::size_t>(index)];
    if (xml::hasAttribute(*component.element, "symmetry")) {
      const std::string value = xml::attribute(*component.element, "symmetry");
      if (value == "x-y-plane") return "x-y";
      if (value == "x-z-plane") return "x-z";
      if (value == "y-z-plane") return "y-z";
      if (value != "inherit") return "none";
    }
    if (component.parentUid.empty()) return "none";
    uid = component.parentUid;
  }
  return "none";
}

gp_Trsf mirrorIn(const std::string& plane) {
  const gp_Dir normal = plane == "x-y" ? gp_Dir(0, 0, 1) : plane == "x-z" ? gp_Dir(0, 1, 0) : gp_Dir(1, 0, 0);
  gp_Trsf mirror;
  mirror.SetMirror(gp_Ax2(gp_Pnt(0, 0, 0), normal));
  return mirror;
}

}  // namespace airshape::model
