#include "component_segment.h"

#include <algorithm>

#include "airshape/error.h"

namespace airshape::wing {

namespace {

/// Segments leading from one element to the other, following inner → outer elements.
std::vector<std::size_t> findPath(const WingGeometry& wing, const std::string& from, const std::string& to) {
  std::vector<std::size_t> path;
  std::string current = from;
  for (std::size_t step = 0; step < wing.segments().size() && current != to; ++step) {
    bool advanced = false;
    for (std::size_t k = 0; k < wing.segments().size(); ++k) {
      if (wing.segments()[k].inner.elementUid == current) {
        path.push_back(k);
        current = wing.segments()[k].outer.elementUid;
        advanced = true;
        break;
      }
    }
    if (!advanced) break;
  }
  if (current != to || path.empty()) return {};
  return path;
}

gp_Pnt chordMiddle(const SegmentEnd& end) { return gp_Pnt((end.leadingEdge().XYZ() + end.trailingEdge().XYZ()) / 2.0); }

}  // namespace

ComponentSegment::ComponentSegment(const WingGeometry& wing, const schema::ComponentSegmentType& definition)
    : uid_(definition.uID) {
  path_ = findPath(wing, definition.fromElementUID, definition.toElementUID);
  if (path_.empty()) path_ = findPath(wing, definition.toElementUID, definition.fromElementUID);
  if (path_.empty())
    throw Error(
        ErrorCode::InvalidModel,
        "no run of segments joins elements '" + definition.fromElementUID + "' and '" + definition.toElementUID + "'",
        {}, definition.xpath);
  elementEtas_.push_back(0.0);
  gp_Pnt previous = chordMiddle(wing.segments()[path_.front()].inner);
  for (std::size_t k : path_) {
    const gp_Pnt next = chordMiddle(wing.segments()[k].outer);
    elementEtas_.push_back(elementEtas_.back() + previous.Distance(next));
    previous = next;
  }
  const double total = elementEtas_.back();
  if (!(total > 0.0)) throw Error(ErrorCode::InvalidModel, "the component segment has no length", {}, definition.xpath);
  for (double& e : elementEtas_) e /= total;
}

ComponentSegment::SegmentPoint ComponentSegment::toSegment(double eta, double xsi) const {
  std::size_t k = path_.size() - 1;
  for (std::size_t i = 0; i < path_.size(); ++i) {
    if (eta < elementEtas_[i + 1]) {
      k = i;
      break;
    }
  }
  const double segmentEta = (eta - elementEtas_[k]) / (elementEtas_[k + 1] - elementEtas_[k]);
  return {path_[k], segmentEta, xsi};
}

double ComponentSegment::toComponentSegment(std::size_t segment, double eta) const {
  for (std::size_t i = 0; i < path_.size(); ++i)
    if (path_[i] == segment) return (1.0 - eta) * elementEtas_[i] + eta * elementEtas_[i + 1];
  throw Error(ErrorCode::InvalidArgument, "the segment is not part of component segment '" + uid_ + "'");
}

std::pair<std::size_t, std::size_t> ComponentSegment::segmentRange() const {
  const auto [first, last] = std::minmax_element(path_.begin(), path_.end());
  return {*first, *last};
}

}  // namespace airshape::wing
