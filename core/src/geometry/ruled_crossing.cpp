#include "airshape/geometry/ruled_crossing.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Bnd_Box.hxx>
#include <Geom2dAPI_Interpolate.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Standard_ConstructionError.hxx>
#include <TColStd_HArray1OfReal.hxx>
#include <TColgp_HArray1OfPnt2d.hxx>
#include <gp_Dir.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>

namespace airshape::geometry {

namespace {
/// How close to a patch's bound, as a share of its parameter range, a parameter may be to be
/// taken at the bound (where the point there lies within the tolerance).
constexpr double kNearBound = 1e-4;
}  // namespace

/// Moves a point lying within the tolerance of a patch's bound onto it, so that a curve ending
/// there ends on the face's edge.
PatchPoint ontoBound(const Patch& patch, PatchPoint point, double tolerance) {
  auto snap = [&](double& parameter, double low, double high) {
    for (const double bound : {low, high}) {
      if (std::abs(parameter - bound) > kNearBound * (high - low)) continue;
      const double kept = parameter;
      parameter = bound;
      if (patch.surface->Value(point.u, point.v).Distance(point.point) > tolerance) parameter = kept;
    }
  };
  snap(point.u, patch.u0, patch.u1);
  snap(point.v, patch.v0, patch.v1);
  point.point = patch.surface->Value(point.u, point.v);
  return point;
}

namespace {

/// The same place of a patch closed on itself (a skin all round) from the other end of its
/// parameters: for a point on the seam, the point at the opposite bound where that lies within
/// the tolerance of it (none, one, or one across each parameter).
std::vector<PatchPoint> acrossSeam(const Patch& patch, const PatchPoint& point, double tolerance) {
  std::vector<PatchPoint> twins;
  auto across = [&](double PatchPoint::*parameter, double low, double high) {
    PatchPoint twin = point;
    const double slack = kNearBound * (high - low);
    if (std::abs(point.*parameter - low) <= slack)
      twin.*parameter = high;
    else if (std::abs(point.*parameter - high) <= slack)
      twin.*parameter = low;
    else
      return;
    twin.point = patch.surface->Value(twin.u, twin.v);
    if (twin.point.Distance(point.point) <= tolerance) twins.push_back(twin);
  };
  across(&PatchPoint::u, patch.u0, patch.u1);
  across(&PatchPoint::v, patch.v0, patch.v1);
  return twins;
}

}  // namespace

Handle(Geom2d_BSplineCurve)
    curveThroughPoints(const std::vector<gp_Pnt2d>& points, const std::vector<double>& parameters) {
  const int n = static_cast<int>(points.size());
  Handle(TColgp_HArray1OfPnt2d) held = new TColgp_HArray1OfPnt2d(1, n);
  Handle(TColStd_HArray1OfReal) at = new TColStd_HArray1OfReal(1, n);
  for (int i = 1; i <= n; ++i) {
    held->SetValue(i, points[static_cast<std::size_t>(i - 1)]);
    at->SetValue(i, parameters[static_cast<std::size_t>(i - 1)]);
  }
  try {
    Geom2dAPI_Interpolate interpolation(held, at, false, 1e-15);
    interpolation.Perform();
    if (!interpolation.IsDone()) return nullptr;
    return interpolation.Curve();
  } catch (const Standard_ConstructionError&) {  // two points at one place
    return nullptr;
  }
}

bool coversAllLines(const std::vector<CrossingPiece>& pieces) {
  if (pieces.empty() || pieces.front().points.front().t > 1e-12 || pieces.back().points.back().t < 1.0 - 1e-12)
    return false;
  for (std::size_t k = 1; k < pieces.size(); ++k)
    if (pieces[k].points.front().t - pieces[k - 1].points.back().t > 1e-9) return false;
  return true;
}

namespace {

/// Where a line of a side meets the skin: on which patch, at which of its parameters.
struct Hit {
  std::size_t patch = 0;
  PatchPoint at;
};

/// Which points of a line count: all of it, or the half from its base (rays from inside a
/// body); s is the point's place along the line's direction from its base.
bool counts(const RuledLines& lines, double s) { return !lines.rays || s >= 0.0; }
/// Only the ruling between its two curves counts (a little beyond them, for rounding).
bool counts(const RulingSegments&, double s) {
  return s >= -RulingSegments::kEndSlack && s <= 1.0 + RulingSegments::kEndSlack;
}

/// Where the line or curve at t meets a patch, from the guess in `point`.
template <class Lines>
bool meets(const Patch& patch, const Lines& lines, double t, PatchPoint& point) {
  const gp_Pnt base = lines.base(t);
  const gp_Vec direction = lines.direction(t);
  if (!meetLine(patch, base, direction, point)) return false;
  point.s = gp_Vec(base, point.point).Dot(direction) / direction.SquareMagnitude();
  return counts(lines, point.s);
}
bool meets(const Patch& patch, const PatchCurves& curves, double t, PatchPoint& point) {
  return meetCurve(patch, curves.patch, curves.fixed(t), curves.alongU, point);
}

/// Whether the line or curve at t surely misses a box.
template <class Lines>
bool passesBy(const Bnd_Box& box, const Lines& lines, double t) {
  return box.IsOut(gp_Lin(lines.base(t), gp_Dir(lines.direction(t))));
}
bool passesBy(const Bnd_Box& box, const PatchCurves& curves, double t) {
  const Handle(Geom_Curve) curve =
      curves.alongU ? curves.patch.surface->VIso(curves.fixed(t)) : curves.patch.surface->UIso(curves.fixed(t));
  const auto spline = Handle(Geom_BSplineCurve)::DownCast(curve);
  if (spline.IsNull()) return false;
  Bnd_Box poles;
  for (int i = 1; i <= spline->NbPoles(); ++i) poles.Add(spline->Pole(i));
  return box.IsOut(poles);
}

/// Where along a line or curve a search starts: the line's own projection decides; a curve
/// is tried from three places over its range.
double startAlong(const RuledLines&, int) { return 0.0; }
double startAlong(const RulingSegments&, int) { return 0.0; }
double startAlong(const PatchCurves& curves, int guess) {
  const Patch& p = curves.patch;
  const double low = curves.alongU ? p.u0 : p.v0, high = curves.alongU ? p.u1 : p.v1;
  return low + (high - low) * (0.5 + guess % 3) / 3.0;
}

/// How far off a second crossing of a line may lie and be left out, as a multiple of the
/// nearest one's distance from the line's base: whole lines may meet the other side of a
/// closed box surface far off; a ruling is a piece of its surface, where every crossing counts.
double ignoredBeyond(const RuledLines&) { return 10.0; }
double ignoredBeyond(const RulingSegments&) { return std::numeric_limits<double>::infinity(); }
double ignoredBeyond(const PatchCurves&) { return std::numeric_limits<double>::infinity(); }

/// Whether every sampled line is searched for a second crossing while the crossing is being
/// followed: a ruled face may meet a skin in several separate lines (a bump through a thin surface),
/// which following one would miss.
bool searchedEveryLine(const RuledLines&) { return false; }
bool searchedEveryLine(const RulingSegments&) { return true; }
bool searchedEveryLine(const PatchCurves&) { return true; }

/// The lines of a ruled surface and where they meet the skin's patches.
template <class Lines>
class Side {
 public:
  Side(const std::vector<Patch>& patches, const Lines& lines) : patches_(patches), lines_(lines) {
    for (const Patch& patch : patches) boxes_.push_back(poleBox(patch));
  }

  /// Where the line at `lambda` meets the patch, from the guess `near`; nothing where it meets
  /// it outside the patch's bounds.
  std::optional<Hit> on(std::size_t patch, double lambda, const PatchPoint& near) const {
    PatchPoint point = near;
    if (!meets(patches_[patch], lines_, lambda, point)) return std::nullopt;
    point.t = lambda;
    return Hit{patch, point};
  }

  /// Every patch the line at `lambda` meets, each found from a grid of starting guesses: the
  /// first point on each, or every point apart by more than `apart` where each line is searched
  /// whole (searchedEveryLine: a ruling may pass through a one-face skin twice).
  std::vector<Hit> search(double lambda, double apart) const {
    constexpr int kGuesses = 6;
    const bool every = searchedEveryLine();
    std::vector<Hit> hits;
    for (std::size_t k = 0; k < patches_.size(); ++k) {
      const Patch& patch = patches_[k];
      if (passesBy(boxes_[k], lines_, lambda)) continue;
      const std::size_t before = hits.size();
      for (int i = 0; i < kGuesses * kGuesses; ++i) {
        PatchPoint guess;
        guess.u = patch.u0 + (patch.u1 - patch.u0) * (0.5 + i / kGuesses) / kGuesses;
        guess.v = patch.v0 + (patch.v1 - patch.v0) * (0.5 + i % kGuesses) / kGuesses;
        guess.s = startAlong(lines_, i);
        const auto hit = on(k, lambda, guess);
        if (!hit) continue;
        const bool known = std::any_of(hits.begin() + static_cast<std::ptrdiff_t>(before), hits.end(),
                                       [&](const Hit& h) { return h.at.point.Distance(hit->at.point) <= apart; });
        if (!known) hits.push_back(*hit);
        if (!every) break;
      }
    }
    return hits;
  }

  const Patch& patch(std::size_t k) const { return patches_[k]; }
  gp_Pnt base(double lambda) const { return lines_.base(lambda); }
  double ignoredBeyond() const { return airshape::geometry::ignoredBeyond(lines_); }
  bool searchedEveryLine() const { return airshape::geometry::searchedEveryLine(lines_); }

 private:
  const std::vector<Patch>& patches_;
  const Lines& lines_;
  std::vector<Bnd_Box> boxes_;
};

using Piece = CrossingPiece;

/// The one point where the line at `lambda` meets the skin, on the patch the crossing goes on
/// over towards `ahead`; nothing when it misses the skin. A line may meet the skin again far
/// off (the far side of a closed box surface): the point nearest the line's base counts where every other
/// lies at least ten times as far from the base. Throws FoldedSkin where the line meets the
/// skin at two points otherwise.
template <class Lines>
std::optional<Hit> entry(const Side<Lines>& side, double lambda, double ahead, double tolerance) {
  std::vector<Hit> hits = side.search(lambda, tolerance);
  if (hits.empty()) return std::nullopt;
  const gp_Pnt base = side.base(lambda);
  std::sort(hits.begin(), hits.end(),
            [&](const Hit& a, const Hit& b) { return base.Distance(a.at.point) < base.Distance(b.at.point); });
  const gp_Pnt nearest = hits.front().at.point;
  const double reach = base.Distance(nearest);
  std::vector<Hit> atNearest;
  for (const Hit& hit : hits)
    if (hit.at.point.Distance(nearest) <= tolerance)
      atNearest.push_back(hit);
    else if (base.Distance(hit.at.point) < side.ignoredBeyond() * reach + tolerance)
      throw FoldedSkin();
  hits = atNearest;
  // A point on the seam of a patch closed on itself is as much at one end of its parameters as
  // at the other; the crossing may go on from either.
  for (const Hit& hit : atNearest)
    for (const PatchPoint& twin : acrossSeam(side.patch(hit.patch), hit.at, tolerance))
      hits.push_back({hit.patch, twin});
  for (const Hit& hit : hits)
    if (side.on(hit.patch, ahead, hit.at)) return Hit{hit.patch, ontoBound(side.patch(hit.patch), hit.at, tolerance)};
  return Hit{hits.front().patch, ontoBound(side.patch(hits.front().patch), hits.front().at, tolerance)};
}

/// The last point of the crossing on the piece's patch before the line at `beyond` (which
/// meets it outside the patch), by bisection, and the line's parameter just past it.
template <class Lines>
std::pair<PatchPoint, double> exitFrom(const Side<Lines>& side, const Piece& piece, double beyond, double tolerance) {
  PatchPoint last = piece.points.back();
  for (int halving = 0; halving < 50; ++halving) {
    const double middle = 0.5 * (last.t + beyond);
    if (const auto hit = side.on(piece.patch, middle, last))
      last = hit->at;
    else
      beyond = middle;
  }
  return {ontoBound(side.patch(piece.patch), last, tolerance), beyond};
}

/// The first point of the crossing on the skin after the line at `outside` (which misses it),
/// by bisection towards `inside`, a hit of a later line.
template <class Lines>
Hit reentry(const Side<Lines>& side, double outside, Hit inside, double tolerance) {
  for (int halving = 0; halving < 50; ++halving) {
    const double middle = 0.5 * (outside + inside.at.t);
    if (const auto hit = side.on(inside.patch, middle, inside.at))
      inside = *hit;
    else
      outside = middle;
  }
  inside.at = ontoBound(side.patch(inside.patch), inside.at, tolerance);
  return inside;
}

/// Whether every point of a piece lies at one place of its patch.
bool heldAtOnePlace(const Piece& piece) {
  for (const PatchPoint& point : piece.points)
    if (point.u != piece.points.front().u || point.v != piece.points.front().v) return false;
  return true;
}

/// The side's crossing of the skin, piece by patch: sampled evenly, each change of patch found
/// by bisection. Where the side runs beyond the skin's edge (past its leading or trailing edge,
/// its root or tip), the region follows that edge, which the skin has already: no piece there.
template <class Lines>
std::optional<std::vector<Piece>> piecesOf(const Side<Lines>& side, double tolerance) {
  constexpr int kSamples = 16;
  const double step = 1.0 / kSamples;
  std::vector<Piece> pieces;
  auto add = [&](Piece& piece, const PatchPoint& point) { piece.points.push_back(point); };
  auto begin = [&](const Hit& hit) {
    pieces.push_back({hit.patch, {}, nullptr});
    add(pieces.back(), hit.at);
  };
  bool onSkin = false;
  double outside = 0.0;  // off the skin: the last line found to miss it
  if (const auto first = entry(side, 0.0, step, tolerance)) {
    begin(*first);
    onSkin = true;
  }
  for (int i = 1, steps = 0; i <= kSamples; ++i) {
    if (++steps > 256) return std::nullopt;
    const double lambda = static_cast<double>(i) / kSamples;
    if (!onSkin) {
      if (const auto hit = entry(side, lambda, std::min(1.0, lambda + step), tolerance)) {
        begin(reentry(side, outside, *hit, tolerance));
        if (hit->at.t > pieces.back().points.back().t) add(pieces.back(), hit->at);
        onSkin = true;
      } else {
        outside = lambda;
      }
      continue;
    }
    Piece& piece = pieces.back();
    if (const auto hit = side.on(piece.patch, lambda, piece.points.back())) {
      if (side.searchedEveryLine()) entry(side, lambda, lambda, tolerance);  // throws where it meets twice
      add(piece, hit->at);
      continue;
    }
    // The crossing left the patch between the last point and this line: onto a neighbouring
    // patch, or off the skin.
    const auto [last, off] = exitFrom(side, piece, lambda, tolerance);
    if (last.t > piece.points.back().t) add(piece, last);
    const auto next = entry(side, off, std::min(1.0, off + step), tolerance);
    if (next && next->patch != piece.patch) {
      begin(*next);
    } else {  // off the skin (or back on the same patch, which the next line takes up)
      onSkin = false;
      outside = off;
    }
    --i;  // this line again, from there
  }
  // A piece over a mere corner of a patch (the crossing passing through a vertex) is left out:
  // its neighbours meet within the vertices' tolerance. So is a piece held at one place (lines
  // passing beyond the skin's corner, each met at the corner): it draws no curve. A piece's ends
  // are put on its patch's bounds where they lie within the tolerance of them; its points
  // between are left where they are, which along a bound close by would put the curve now on
  // the bound, now off it.
  std::vector<Piece> kept;
  for (Piece& piece : pieces) {
    if (piece.points.back().t - piece.points.front().t <= 1e-9) continue;
    const Patch& patch = side.patch(piece.patch);
    piece.points.front() = ontoBound(patch, piece.points.front(), tolerance);
    piece.points.back() = ontoBound(patch, piece.points.back(), tolerance);
    if (heldAtOnePlace(piece)) continue;
    kept.push_back(piece);
  }
  for (const Piece& piece : kept)
    if (piece.points.size() < 2) return std::nullopt;
  return kept;
}

/// The curve through a piece's points in its patch's parameters, by the side's parameter.
/// Where the crossing stays at one place over a few lines (lines passing through the skin's
/// edge meet it at the edge's point, held there), the place is taken once, at its first line
/// (at the piece's last line where the piece ends there, so that the curve spans the piece).
Handle(Geom2d_BSplineCurve) curveThrough(const Piece& piece) {
  std::vector<gp_Pnt2d> points;
  std::vector<double> parameters;
  for (const PatchPoint& point : piece.points) {
    const gp_Pnt2d place(point.u, point.v);
    if (!points.empty() && points.back().IsEqual(place, 0.0)) {
      if (&point == &piece.points.back()) parameters.back() = point.t;
      continue;
    }
    points.push_back(place);
    parameters.push_back(point.t);
  }
  if (points.size() < 2) return nullptr;
  return curveThroughPoints(points, parameters);
}

/// Whether a point lies on one of its patch's bounds.
bool onBound(const Patch& patch, const PatchPoint& point) {
  return point.u == patch.u0 || point.u == patch.u1 || point.v == patch.v0 || point.v == patch.v1;
}

/// Adds points halfway between two where the curve strays from the crossing by more than the
/// tolerance; true when it strays nowhere.
template <class Lines>
bool followsCrossing(const Side<Lines>& side, Piece& piece, const Handle(Geom2d_BSplineCurve) & curve, double tolerance,
                     bool& failed) {
  const Patch& patch = side.patch(piece.patch);
  std::vector<PatchPoint> denser{piece.points.front()};
  bool close = true;
  for (std::size_t i = 1; i < piece.points.size(); ++i) {
    const double middle = 0.5 * (piece.points[i - 1].t + piece.points[i].t);
    const auto hit = side.on(piece.patch, middle, piece.points[i - 1]);
    if (!hit && (onBound(patch, piece.points[i - 1]) || onBound(patch, piece.points[i]))) {
      // An end put onto the patch's bound from a line that passes just beyond it: the lines
      // between pass beyond it too; the crossing runs on the bound there.
      denser.push_back(piece.points[i]);
      continue;
    }
    if (!hit) {
      failed = true;
      return false;
    }
    const gp_Pnt2d uv = curve->Value(middle);
    if (patch.surface->Value(uv.X(), uv.Y()).Distance(hit->at.point) > tolerance) {
      close = false;
      denser.push_back(hit->at);
    }
    denser.push_back(piece.points[i]);
  }
  piece.points = denser;
  return close;
}

template <class Lines>
std::optional<std::vector<CrossingPiece>> crossingOfLines(const std::vector<Patch>& patches, const Lines& lines,
                                                          double tolerance) {
  const Side<Lines> side(patches, lines);
  auto pieces = piecesOf(side, tolerance);
  if (!pieces) return std::nullopt;
  // Where a line meets the skin tangentially at a piece's end (a cell's corner on the leading
  // edge), the crossing goes there like a square root of t: the points crowd towards that end
  // over many rounds, a few more each round: each round halves the steps next to it, so some
  // forty rounds take it from a sixteenth of the lines down to rounding.
  constexpr std::size_t kMostPoints = 1000;
  constexpr int kMostRounds = 64;
  for (CrossingPiece& piece : *pieces) {
    piece.curve = curveThrough(piece);
    bool failed = false;
    for (int round = 0; piece.curve && !followsCrossing(side, piece, piece.curve, tolerance, failed); ++round) {
      if (failed || round == kMostRounds || piece.points.size() > kMostPoints) return std::nullopt;
      piece.curve = curveThrough(piece);
    }
    if (!piece.curve) return std::nullopt;
  }
  return pieces;
}

}  // namespace

std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches, const RuledLines& lines,
                                                        double tolerance) {
  return crossingOfLines(patches, lines, tolerance);
}

std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches,
                                                        const RulingSegments& rulings, double tolerance) {
  return crossingOfLines(patches, rulings, tolerance);
}

std::optional<std::vector<CrossingPiece>> ruledCrossing(const std::vector<Patch>& patches, const PatchCurves& curves,
                                                        double tolerance) {
  return crossingOfLines(patches, curves, tolerance);
}

}  // namespace airshape::geometry
