#include "symmetry_plane.h"

#include <algorithm>
#include <string>

#include <gmsh.h>

#include "airshape/error.h"
#include "gmsh_nodes.h"
#include "gmsh_session.h"

namespace airshape::meshing {

namespace {

/// The closed loops of boundary edges (each as its triangle runs it) around a triangulated
/// plane region, the widest first.
std::vector<std::vector<std::size_t>> boundaryLoops(const std::vector<double>& coordinates, const Triangles& region) {
  std::map<std::pair<std::size_t, std::size_t>, int> uses;
  for (std::size_t t = 0; t < region.size(); t += 3)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t a = region[t + c], b = region[t + (c + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  std::map<std::size_t, std::size_t> next;
  for (std::size_t t = 0; t < region.size(); t += 3)
    for (std::size_t c = 0; c < 3; ++c) {
      const std::size_t a = region[t + c], b = region[t + (c + 1) % 3];
      if (uses[{std::min(a, b), std::max(a, b)}] == 1 && !next.emplace(a, b).second)
        throw Error(ErrorCode::InvalidArgument,
                    "--boundary-layer: the symmetry plane's mesh touches itself at a node; it cannot be remeshed");
    }
  std::vector<std::vector<std::size_t>> loops;
  while (!next.empty()) {
    std::vector<std::size_t> loop{next.begin()->first};
    for (auto at = next.find(loop.back()); at != next.end(); at = next.find(loop.back())) {
      const std::size_t following = at->second;
      next.erase(at);
      if (following != loop.front()) loop.push_back(following);
    }
    loops.push_back(loop);
  }
  const auto width = [&](const std::vector<std::size_t>& loop) {
    double low = 1e300, high = -1e300;
    for (std::size_t node : loop)
      low = std::min(low, coordinates[3 * node]), high = std::max(high, coordinates[3 * node]);
    return high - low;
  };
  std::sort(loops.begin(), loops.end(), [&](const auto& a, const auto& b) { return width(a) > width(b); });
  return loops;
}

}  // namespace

Triangles remeshedSymmetryPlane(std::vector<double>& coordinates, const Triangles& plane,
                                const std::unordered_map<std::size_t, std::size_t>& topOf, const Sizes& sizes) {
  std::vector<std::vector<std::size_t>> loops = boundaryLoops(coordinates, plane);
  std::map<Position, std::size_t> known;
  Triangles triangles;
  callGmsh("meshing the symmetry plane around the boundary layer", [&] {
    std::string domain;
    gmsh::model::getCurrent(domain);
    gmsh::model::add("symmetry plane");
    std::map<std::size_t, int> pointOfNode;
    std::vector<int> curveLoops, lines;
    std::vector<double> innerLines;
    for (std::size_t l = 0; l < loops.size(); ++l) {
      std::vector<int> loopLines;
      for (std::size_t& node : loops[l]) {
        if (const auto top = topOf.find(node); top != topOf.end()) node = top->second;
        if (pointOfNode.count(node) == 0) {
          pointOfNode[node] =
              gmsh::model::geo::addPoint(coordinates[3 * node], coordinates[3 * node + 1], coordinates[3 * node + 2]);
          known[positionOf(coordinates, node)] = node;
        }
      }
      for (std::size_t i = 0; i < loops[l].size(); ++i) {
        const int line =
            gmsh::model::geo::addLine(pointOfNode[loops[l][i]], pointOfNode[loops[l][(i + 1) % loops[l].size()]]);
        loopLines.push_back(line);
        lines.push_back(line);
        if (l > 0) innerLines.push_back(line);
      }
      curveLoops.push_back(gmsh::model::geo::addCurveLoop(loopLines));
    }
    gmsh::model::geo::addPlaneSurface(curveLoops);
    gmsh::model::geo::synchronize();
    for (int line : lines) gmsh::model::mesh::setTransfiniteCurve(line, 2);  // its two ends only
    setFluidSizes("EdgesList", innerLines, sizes);
    gmsh::model::mesh::generate(2);
    triangles = elementsOfType(kTriangle, indicesOfGmshNodes(coordinates, known));
    gmsh::model::remove();
    gmsh::model::setCurrent(domain);
  });
  return triangles;
}

}  // namespace airshape::meshing
