#include "airshape/geometry/coons_patches.h"

#include <algorithm>
#include <string>

#include <BSplCLib.hxx>
#include <GeomFill_BSplineCurves.hxx>
#include <GeomFill_Profiler.hxx>
#include <Precision.hxx>
#include <Standard_Failure.hxx>
#include <TColStd_Array1OfReal.hxx>

#include "airshape/error.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/curve_concatenation.h"
#include "airshape/parallel_for.h"

namespace airshape::geometry {

namespace {

/// Relative tolerance under which two knots count as the same.
constexpr double kSameKnot = 1e-6;

/// The part [from, to] of a curve, keeping its parametrisation. On a closed curve the
/// part may run past its end (to > last parameter): it then continues from the start.
Handle(Geom_BSplineCurve) piece(const Handle(Geom_BSplineCurve) & curve, double from, double to) {
  Handle(Geom_BSplineCurve) whole = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
  if (whole->IsPeriodic()) whole->SetNotPeriodic();
  const double first = whole->FirstParameter(), last = whole->LastParameter(), period = last - first;
  const double tolerance = 1e-12 * std::max(1.0, std::abs(period));
  if (to <= last + tolerance || to - period <= first + tolerance) {  // nothing past the end
    whole->Segment(from, std::min(to, last));
    return whole;
  }
  Handle(Geom_BSplineCurve) head = Handle(Geom_BSplineCurve)::DownCast(whole->Copy());
  head->Segment(first, to - period);
  TColStd_Array1OfReal knots(1, head->NbKnots());
  head->Knots(knots);
  for (double& knot : knots) knot += period;
  head->SetKnots(knots);
  if (from >= last - tolerance) return head;
  whole->Segment(from, last);
  return concatenateCurves({whole, head});
}

/// Whether two curves have the same degree and the same knots (within kSameKnot).
bool sameDistribution(const Geom_BSplineCurve& a, const Geom_BSplineCurve& b) {
  if (a.IsRational() || b.IsRational() || a.Degree() != b.Degree() || a.NbPoles() != b.NbPoles() ||
      a.NbKnots() != b.NbKnots())
    return false;
  for (int j = 1; j <= a.NbKnots(); ++j) {
    const double tolerance =
        std::max(kSameKnot * (std::abs(a.Knot(j)) + std::abs(b.Knot(j))) / 2.0, Precision::PConfusion());
    if (a.Multiplicity(j) != b.Multiplicity(j) || std::abs(a.Knot(j) - b.Knot(j)) >= tolerance) return false;
  }
  return true;
}

/// Gives two opposite boundaries one degree and one knot vector: knots that already agree
/// are averaged, otherwise OCCT's profiler merges them (reparametrising linearly).
void matchOpposite(Handle(Geom_BSplineCurve) & a, Handle(Geom_BSplineCurve) & b) {
  if (sameDistribution(*a, *b)) {
    TColStd_Array1OfReal knots(1, a->NbKnots());
    for (int j = 1; j <= a->NbKnots(); ++j) knots(j) = (a->Knot(j) + b->Knot(j)) / 2.0;
    a->SetKnots(knots);
    b->SetKnots(knots);
    return;
  }
  double shortest = RealLast();
  for (const auto* curve : {a.get(), b.get()})
    for (int j = 1; j < curve->NbKnots(); ++j) shortest = std::min(shortest, curve->Knot(j + 1) - curve->Knot(j));
  GeomFill_Profiler profiler;
  profiler.AddCurve(a);
  profiler.AddCurve(b);
  profiler.Perform(std::max(shortest * kSameKnot, Precision::Confusion()));
  a = Handle(Geom_BSplineCurve)::DownCast(profiler.Curve(1));
  b = Handle(Geom_BSplineCurve)::DownCast(profiler.Curve(2));
}

/// The filling needs four poles or more on each boundary: raise the degree, or split the
/// longest span, of both opposite boundaries alike.
void ensureFourPoles(Handle(Geom_BSplineCurve) & a, Handle(Geom_BSplineCurve) & b) {
  while (a->NbPoles() < 4) {
    const int degree = a->Degree();
    if (degree < Geom_BSplineCurve::MaxDegree()) {
      a->IncreaseDegree(degree + 1);
      b->IncreaseDegree(degree + 1);
      continue;
    }
    int longest = a->FirstUKnotIndex();
    for (int j = a->FirstUKnotIndex(); j < a->LastUKnotIndex(); ++j)
      if (a->Knot(j + 1) - a->Knot(j) > a->Knot(longest + 1) - a->Knot(longest)) longest = j;
    const double middle = 0.5 * (a->Knot(longest) + a->Knot(longest + 1));
    a->InsertKnot(middle, degree - 1);
    b->InsertKnot(middle, degree - 1);
  }
}

void normaliseParameters(Geom_BSplineSurface& surface) {
  TColStd_Array1OfReal uKnots(1, surface.NbUKnots()), vKnots(1, surface.NbVKnots());
  surface.UKnots(uKnots);
  surface.VKnots(vKnots);
  BSplCLib::Reparametrize(0.0, 1.0, uKnots);
  BSplCLib::Reparametrize(0.0, 1.0, vKnots);
  surface.SetUKnots(uKnots);
  surface.SetVKnots(vKnots);
}

/// The patches of one row side by side in u (cell l over [l, l+1]), joined C0. They share
/// their v knots and degrees; each keeps its own u knots (made compatible in u too, every cell
/// carried every other's: a guided body's rings had 1,900 u knots, mostly a millionth apart,
/// instead of 130).
Handle(Geom_BSplineSurface) sideBySide(std::vector<Handle(Geom_BSplineSurface)> patches) {
  makeCompatibleAlongV(patches);
  const Geom_BSplineSurface& first = *patches.front();
  const int uDegree = first.UDegree(), rows = first.NbVPoles();
  int columns = 1, knotCount = 1;
  for (const auto& patch : patches) columns += patch->NbUPoles() - 1, knotCount += patch->NbUKnots() - 1;
  TColgp_Array2OfPnt poles(1, columns, 1, rows);
  TColStd_Array1OfReal uKnots(1, knotCount);
  TColStd_Array1OfInteger uMults(1, knotCount);
  int column = 0, knot = 0;
  for (std::size_t c = 0; c < patches.size(); ++c) {
    const Geom_BSplineSurface& patch = *patches[c];
    for (int i = (c == 0 ? 1 : 2); i <= patch.NbUPoles(); ++i) {
      ++column;
      for (int j = 1; j <= rows; ++j) poles(column, j) = patch.Pole(i, j);
    }
    for (int j = (c == 0 ? 1 : 2); j <= patch.NbUKnots(); ++j) {
      ++knot;
      uKnots(knot) = static_cast<double>(c) + patch.UKnot(j);
      const bool cellEnd = j == 1 || j == patch.NbUKnots();
      const bool rowEnd = knot == 1 || knot == knotCount;
      uMults(knot) = cellEnd ? (rowEnd ? uDegree + 1 : uDegree) : patch.UMultiplicity(j);
    }
  }
  TColStd_Array1OfReal vKnots(1, first.NbVKnots());
  TColStd_Array1OfInteger vMults(1, first.NbVKnots());
  first.VKnots(vKnots);
  first.VMultiplicities(vMults);
  return new Geom_BSplineSurface(poles, uKnots, vKnots, uMults, vMults, uDegree, first.VDegree());
}

}  // namespace

Handle(Geom_BSplineSurface)
    coonsPatch(Handle(Geom_BSplineCurve) bottom, Handle(Geom_BSplineCurve) right, Handle(Geom_BSplineCurve) top,
               Handle(Geom_BSplineCurve) left, PatchBlending blending) {
  matchOpposite(bottom, top);
  matchOpposite(right, left);
  ensureFourPoles(bottom, top);
  ensureFourPoles(right, left);
  try {
    GeomFill_BSplineCurves filling;
    filling.Init(bottom, right, top, left,
                 blending == PatchBlending::Rounded ? GeomFill_CoonsStyle : GeomFill_StretchStyle);
    Handle(Geom_BSplineSurface) patch = Handle(Geom_BSplineSurface)::DownCast(filling.Surface()->Copy());
    normaliseParameters(*patch);
    return patch;
  } catch (const Standard_Failure& failure) {
    throw Error(ErrorCode::InvalidModel,
                std::string("a Coons patch cannot be filled: ") +
                    (failure.GetMessageString() ? failure.GetMessageString() : "OCCT failure"));
  }
}

std::vector<Handle(Geom_BSplineSurface)> buildCoonsPatchRows(
    const std::vector<Handle(Geom_BSplineCurve)>& profiles, const std::vector<Handle(Geom_BSplineCurve)>& guides,
    const KnownCrossings& crossings, const std::function<PatchBlending(std::size_t, std::size_t)>& blending,
    const std::function<std::string(std::size_t, std::size_t)>& describe) {
  if (profiles.size() < 2 || guides.size() < 2)
    throw Error(ErrorCode::InvalidModel, "a patch network needs two profiles and two guides at least");
  const auto& p = crossings.profileParameters;
  const auto& g = crossings.guideParameters;
  // Rows are independent: they are filled on every core (a guided body's patches were
  // two thirds of its building).
  std::vector<Handle(Geom_BSplineSurface)> rows(profiles.size() - 1);
  parallelFor(rows.size(), [&](std::size_t row) {
    const auto k = static_cast<Eigen::Index>(row);
    std::vector<Handle(Geom_BSplineSurface)> cells;
    for (Eigen::Index l = 0; l + 1 < static_cast<Eigen::Index>(guides.size()); ++l) {
      const auto& lower = profiles[static_cast<std::size_t>(k)];
      const auto& upper = profiles[static_cast<std::size_t>(k + 1)];
      const auto& first = guides[static_cast<std::size_t>(l)];
      const auto& second = guides[static_cast<std::size_t>(l + 1)];
      const std::string cell = describe ? describe(static_cast<std::size_t>(k), static_cast<std::size_t>(l))
                                        : "the cell between profiles " + std::to_string(k + 1) + " and " +
                                              std::to_string(k + 2) + " and guides " + std::to_string(l + 1) + " and " +
                                              std::to_string(l + 2);
      if (!(p(k, l + 1) > p(k, l)) || !(p(k + 1, l + 1) > p(k + 1, l)) || !(g(k + 1, l) > g(k, l)) ||
          !(g(k + 1, l + 1) > g(k, l + 1)))
        throw Error(ErrorCode::InvalidModel, cell + " is empty: two curves cross at one point or out of order");
      try {
        cells.push_back(coonsPatch(piece(lower, p(k, l), p(k, l + 1)), piece(second, g(k, l + 1), g(k + 1, l + 1)),
                                   piece(upper, p(k + 1, l), p(k + 1, l + 1)), piece(first, g(k, l), g(k + 1, l)),
                                   blending(static_cast<std::size_t>(k), static_cast<std::size_t>(l))));
      } catch (const Standard_Failure& failure) {
        throw Error(
            ErrorCode::InvalidModel,
            cell + " cannot be filled: " + (failure.GetMessageString() ? failure.GetMessageString() : "OCCT failure"));
      }
    }
    rows[row] = sideBySide(cells);
  });
  return rows;
}

}  // namespace airshape::geometry
