// Curve interpolation, approximation and compatibility meet their constraints.
#include <algorithm>
#include <cmath>

#include <gtest/gtest.h>

#include "airshape/error.h"
#include "airshape/geometry/compatibility.h"
#include "airshape/geometry/curve_approximation.h"
#include "airshape/geometry/curve_interpolation.h"
#include "airshape/geometry/skinning.h"

namespace airshape::geometry {
namespace {

std::vector<gp_Pnt> wavyPoints(int count, bool closed) {
  std::vector<gp_Pnt> points;
  for (int i = 0; i < count; ++i) {
    const double a = 2.0 * M_PI * i / (closed ? count - 1 : count);
    points.emplace_back(std::cos(a) * (1.0 + 0.2 * (i % 3)), std::sin(a), 0.3 * std::sin(3 * a));
  }
  if (closed) points.back() = points.front();
  return points;
}

double maxMiss(const Geom_BSplineCurve& curve, const std::vector<gp_Pnt>& points,
               const std::vector<double>& parameters) {
  double miss = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) miss = std::max(miss, curve.Value(parameters[i]).Distance(points[i]));
  return miss;
}

TEST(Interpolation, OpenCurvesPassThroughTheirPoints) {
  const auto points = wavyPoints(12, false);
  for (double exponent : {1.0, 0.5}) {
    const auto parameters = chordParameters(points, exponent);
    for (int degree : {1, 2, 3, 5}) {
      const auto curve = interpolateCurve(points, parameters, degree);
      EXPECT_EQ(curve->Degree(), degree);
      EXPECT_LT(maxMiss(*curve, points, parameters), 1e-10);
    }
  }
  // Two points allow degree 1 only.
  const std::vector<gp_Pnt> two = {gp_Pnt(0, 0, 0), gp_Pnt(1, 2, 3)};
  EXPECT_EQ(interpolateCurve(two, {0.0, 1.0}, 3)->Degree(), 1);
}

TEST(Interpolation, ClosedCurvesArePeriodicAndSmoothAcrossTheSeam) {
  const auto points = wavyPoints(15, true);
  const auto parameters = chordParameters(points, 0.5);
  for (int degree : {2, 3, 4}) {  // even degrees use the shifting method
    const auto curve = interpolateCurve(points, parameters, degree, true);
    EXPECT_TRUE(curve->IsPeriodic());
    EXPECT_LT(maxMiss(*curve, points, parameters), 1e-10) << "degree " << degree;
    const double seam = curve->FirstParameter(), end = curve->LastParameter();
    for (int order = 1; order < degree; ++order)
      EXPECT_LT((curve->DN(seam, order) - curve->DN(end, order)).Magnitude(),
                1e-8 * (1 + curve->DN(seam, order).Magnitude()));
  }
}

TEST(Interpolation, KinksBecomeCorners) {
  std::vector<gp_Pnt> points = {gp_Pnt(0, 0, 0),   gp_Pnt(1, 0.2, 0), gp_Pnt(2, 0, 0),
                                gp_Pnt(2.2, 1, 0), gp_Pnt(2, 2, 0),   gp_Pnt(1.5, 3, 0)};
  const auto parameters = chordParameters(points);
  const auto curve = interpolateCurve(points, parameters, 3, false, {2});
  EXPECT_LT(maxMiss(*curve, points, parameters), 1e-10);
  const double corner = parameters[2];
  const gp_Vec before = curve->DN(corner - 1e-9, 1), after = curve->DN(corner + 1e-9, 1);
  EXPECT_GT(before.Angle(after), 0.5) << "the curve turns sharply at the kink";
}

TEST(Interpolation, BadInputIsAnError) {
  EXPECT_THROW(interpolateCurve({gp_Pnt(0, 0, 0)}, {0.0}), Error);
  EXPECT_THROW(interpolateCurve({gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0)}, {0.0, 0.0}), Error);
  EXPECT_THROW(chordParameters({gp_Pnt(1, 1, 1), gp_Pnt(1, 1, 1)}), Error);
  EXPECT_THROW(interpolateCurve({gp_Pnt(0, 0, 0), gp_Pnt(1, 0, 0), gp_Pnt(2, 1, 0)}, {0.0, 0.5, 1.0}, 3, true), Error);
}

TEST(Approximation, LeastSquaresMeetsItsInterpolationConstraints) {
  std::vector<double> parameters;
  PoleMatrix points(200, 3);
  for (int i = 0; i < 200; ++i) {
    const double t = i / 199.0;
    parameters.push_back(t);
    points.row(i) << t, std::sin(6 * t) + 0.01 * std::sin(90 * t), std::cos(4 * t);
  }
  InterpolationConstraints constraints;
  constraints.parameters = {0.0, 0.37, 1.0};
  constraints.points.resize(3, 3);
  constraints.points << 0, 0.5, 1, 0.37, 2.0, 0, 1, -1, 0.5;  // deliberately off the data
  for (bool periodic : {false, true}) {
    const KnotVector space = periodic ? periodicUniformKnots(0, 1, 15, 3) : uniformKnots(0, 1, 15, 3);
    InterpolationConstraints used = constraints;
    if (periodic) {  // a periodic curve has one point at 0 and 1
      used.parameters = {0.0, 0.37};
      used.points = constraints.points.topRows(2);
    }
    const auto curve = makeCurve(space, approximatePoles(space, parameters, points, used));
    for (std::size_t i = 0; i < used.parameters.size(); ++i) {
      const gp_Pnt wanted(used.points(static_cast<Eigen::Index>(i), 0), used.points(static_cast<Eigen::Index>(i), 1),
                          used.points(static_cast<Eigen::Index>(i), 2));
      EXPECT_LT(curve->Value(used.parameters[i]).Distance(wanted), 1e-10);
    }
  }
}

/// The largest distance of the samples from the curve (their feet, not their parameters).
double largestDistance(const Geom_BSplineCurve& curve, const PoleMatrix& points) {
  double largest = 0.0;
  for (Eigen::Index i = 0; i < points.rows(); ++i) {
    double nearest = 1e300;
    for (int k = 0; k <= 4000; ++k)
      nearest = std::min(nearest, curve.Value(k / 4000.0).Distance(gp_Pnt(points(i, 0), points(i, 1), points(i, 2))));
    largest = std::max(largest, nearest);
  }
  return largest;
}

TEST(Approximation, CorrectedParametersFitCloserAndKeepTheConstraints) {
  // Points crowded at one end of a quarter circle, given evenly spread parameters: the plain
  // fit is pulled along the curve; moving each parameter to its sample's foot and fitting
  // again lies closer. The constraints stay where they were put.
  std::vector<double> parameters;
  PoleMatrix points(41, 3);
  for (int i = 0; i <= 40; ++i) {
    const double a = 0.5 * M_PI * std::pow(i / 40.0, 2);
    parameters.push_back(i / 40.0);
    points.row(i) << std::cos(a), std::sin(a), 0.0;
  }
  InterpolationConstraints constraints;
  constraints.parameters = {0.0, 1.0};
  constraints.points.resize(2, 3);
  constraints.points << 1, 0, 0, 0, 1, 0;
  const KnotVector space = uniformKnots(0, 1, 6, 3);
  const auto plain = makeCurve(space, approximatePoles(space, parameters, points, constraints));
  const auto unchanged = fitCorrectingParameters(space, parameters, points, constraints, FitError::Largest, 0);
  for (int k = 0; k <= 10; ++k) EXPECT_LT(plain->Value(k / 10.0).Distance(unchanged->Value(k / 10.0)), 1e-14);
  for (FitError measure : {FitError::Largest, FitError::RootMeanSquare}) {
    const auto corrected = fitCorrectingParameters(space, parameters, points, constraints, measure);
    EXPECT_LT(largestDistance(*corrected, points), 0.7 * largestDistance(*plain, points));
    EXPECT_LT(corrected->Value(0.0).Distance(gp_Pnt(1, 0, 0)), 1e-12);
    EXPECT_LT(corrected->Value(1.0).Distance(gp_Pnt(0, 1, 0)), 1e-12);
  }
}

TEST(Approximation, ASeamAtTheEndPointsFollowsTheirCorrectedParameters) {
  // A closed outline, a circle squashed on one side, its points spread unevenly: the
  // corrections move the parameters of the first and the last point (both samples) off the
  // range's ends. Closed at the range's ends the curve's ends meet, C2; closed at the end
  // points, as the reference fits fuselage profiles, its conditions hold at their corrected
  // parameters and the curve's own ends part.
  std::vector<gp_Pnt> points;
  for (int i = 0; i <= 48; ++i) {
    const double a = 2.0 * M_PI * std::pow(i / 48.0, 1.3);
    points.emplace_back(0.0, std::sin(a) * (std::sin(a) > 0 ? 1.0 : 0.6), std::cos(a));
  }
  points.back() = points.front();
  const std::vector<double> parameters = chordParameters(points, 0.5);
  InterpolationConstraints seam;
  seam.seamContinuity = 2;
  seam.freeSeam = true;
  const KnotVector space = uniformKnots(0, 1, 12, 3);
  const auto atEnds = fitPointsCorrectingParameters(space, parameters, points, {}, FitError::Largest, seam, 5);
  EXPECT_LT(atEnds->StartPoint().Distance(atEnds->EndPoint()), 1e-12);
  const auto atPoints =
      fitPointsCorrectingParameters(space, parameters, points, {}, FitError::Largest, seam, 5, SeamAt::EndPoints);
  EXPECT_GT(atPoints->StartPoint().Distance(atPoints->EndPoint()), 1e-4);
  // Uncorrected, both are the same closed curve: the end points sit at the range's ends.
  const auto plain =
      fitPointsCorrectingParameters(space, parameters, points, {}, FitError::Largest, seam, 0, SeamAt::EndPoints);
  for (int k = 0; k <= 10; ++k)
    EXPECT_LT(
        plain->Value(k / 10.0).Distance(
            fitPointsCorrectingParameters(space, parameters, points, {}, FitError::Largest, seam, 0)->Value(k / 10.0)),
        1e-12);
}

TEST(Approximation, TooFewSamplesIsAnError) {
  const KnotVector space = uniformKnots(0, 1, 10, 3);
  PoleMatrix points(3, 3);
  points.setZero();
  EXPECT_THROW(approximatePoles(space, {0.0, 0.5, 1.0}, points), Error);
}

TEST(Compatibility, DegreeElevationAndKnotInsertionKeepTheGeometry) {
  const auto points = wavyPoints(9, false);
  const auto a = interpolateCurve(points, chordParameters(points), 2);
  const auto b = interpolateCurve(points, chordParameters(points, 0.5), 3);
  std::vector<Handle(Geom_BSplineCurve)> curves = {Handle(Geom_BSplineCurve)::DownCast(a->Copy()),
                                                   Handle(Geom_BSplineCurve)::DownCast(b->Copy())};
  makeCompatible(curves);
  ASSERT_EQ(curves[0]->Degree(), curves[1]->Degree());
  ASSERT_EQ(curves[0]->NbKnots(), curves[1]->NbKnots());
  for (int i = 1; i <= curves[0]->NbKnots(); ++i) {
    EXPECT_NEAR(curves[0]->Knot(i), curves[1]->Knot(i), 1e-14);
    EXPECT_EQ(curves[0]->Multiplicity(i), curves[1]->Multiplicity(i));
  }
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    EXPECT_LT(curves[0]->Value(t).Distance(a->Value(t)), 1e-12);
    EXPECT_LT(curves[1]->Value(t).Distance(b->Value(t)), 1e-12);
  }
}

TEST(Compatibility, PeriodicAndClampedCurvesMix) {
  const auto closedPoints = wavyPoints(11, true);
  const auto periodic = interpolateCurve(closedPoints, chordParameters(closedPoints, 0.5), 3, true);
  std::vector<gp_Pnt> square = {gp_Pnt(1, 0, 0), gp_Pnt(0, 1, 0), gp_Pnt(-1, 0, 0), gp_Pnt(0, -1, 0), gp_Pnt(1, 0, 0)};
  const auto clamped = interpolateCurve(square, chordParameters(square), 3, false, {1, 2, 3});
  std::vector<Handle(Geom_BSplineCurve)> curves = {Handle(Geom_BSplineCurve)::DownCast(periodic->Copy()),
                                                   Handle(Geom_BSplineCurve)::DownCast(clamped->Copy())};
  makeCompatible(curves);
  EXPECT_EQ(curves[0]->NbPoles(), curves[1]->NbPoles());
  EXPECT_FALSE(curves[0]->IsPeriodic());
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    EXPECT_LT(curves[0]->Value(t).Distance(periodic->Value(t)), 1e-12);
    EXPECT_LT(curves[1]->Value(t).Distance(clamped->Value(t)), 1e-12);
  }
}

TEST(Compatibility, PeriodicCurvesWithADoubleStartKnotShareOnePeriod) {
  // Two closed cubics, one with the knot that starts (and ends) its period doubled. Made
  // compatible, the other's start knot is doubled too (once: the period's end is the same knot),
  // both keep their shape and run over one knot vector.
  const auto closedPoints = wavyPoints(11, true);
  const auto doubled = interpolateCurve(closedPoints, chordParameters(closedPoints), 3, true);
  doubled->InsertKnot(doubled->FirstParameter(), 2, 1e-12, false);
  const auto single = interpolateCurve(closedPoints, chordParameters(closedPoints, 0.5), 3, true);
  ASSERT_EQ(doubled->Multiplicity(1), 2);
  std::vector<Handle(Geom_BSplineCurve)> curves = {Handle(Geom_BSplineCurve)::DownCast(doubled->Copy()),
                                                   Handle(Geom_BSplineCurve)::DownCast(single->Copy())};
  makeCompatible(curves);
  ASSERT_TRUE(curves[0]->IsPeriodic() && curves[1]->IsPeriodic());
  ASSERT_EQ(curves[0]->NbKnots(), curves[1]->NbKnots());
  for (int i = 1; i <= curves[0]->NbKnots(); ++i) {
    EXPECT_NEAR(curves[0]->Knot(i), curves[1]->Knot(i), 1e-12);
    EXPECT_EQ(curves[0]->Multiplicity(i), curves[1]->Multiplicity(i)) << "knot " << i;
  }
  EXPECT_EQ(curves[0]->NbPoles(), curves[1]->NbPoles());
  for (int i = 0; i <= 100; ++i) {
    const double t = i / 100.0;
    EXPECT_LT(curves[0]->Value(t).Distance(doubled->Value(t)), 1e-12);
    EXPECT_LT(curves[1]->Value(t).Distance(single->Value(t)), 1e-12);
  }
}

/// A closed band about the z axis through rings at the given heights, sampled at `around`
/// angles, periodic around with the given degree.
Handle(Geom_BSplineSurface) band(int around, int degreeAround) {
  const std::vector<double> heights{0.0, 0.5, 1.0};
  std::vector<double> turns;
  for (int j = 0; j <= around; ++j) turns.push_back(static_cast<double>(j) / around);
  // Rows around (the closing turn belongs to no row), each up the heights.
  std::vector<std::vector<gp_Pnt>> rows;
  for (int j = 0; j < around; ++j) {
    rows.emplace_back();
    for (double h : heights)
      rows.back().emplace_back((1 + 0.2 * h) * std::cos(2 * M_PI * turns[j]),
                               (1 + 0.2 * h) * std::sin(2 * M_PI * turns[j]), h);
  }
  return interpolateGrid(rows, heights, skinningSpace(heights, 2, false), turns,
                         skinningSpace(turns, degreeAround, true));
}

TEST(Compatibility, PeriodicSurfacesWhosePeriodsStartApartShareOneRange) {
  // Three sites around at degree 2 put the period's knots at 1/6, 1/2, 5/6 (from 1/6 to 7/6);
  // twelve at degree 3 start it at 0. Made compatible, both run over one range.
  const Handle(Geom_BSplineSurface) few = band(3, 2), many = band(12, 3);
  std::vector<Handle(Geom_BSplineSurface)> surfaces = {Handle(Geom_BSplineSurface)::DownCast(few->Copy()),
                                                       Handle(Geom_BSplineSurface)::DownCast(many->Copy())};
  makeCompatible(surfaces);
  ASSERT_EQ(surfaces[0]->NbVKnots(), surfaces[1]->NbVKnots());
  for (int i = 1; i <= surfaces[0]->NbVKnots(); ++i) {
    EXPECT_NEAR(surfaces[0]->VKnot(i), surfaces[1]->VKnot(i), 1e-12);
    EXPECT_EQ(surfaces[0]->VMultiplicity(i), surfaces[1]->VMultiplicity(i)) << "knot " << i;
  }
  // The knot that starts the period also ends it: raised once to the degree-raised few's 2.
  EXPECT_EQ(surfaces[1]->VMultiplicity(1), 2);
  EXPECT_EQ(surfaces[0]->NbVPoles(), surfaces[1]->NbVPoles());
  for (int i = 0; i <= 10; ++i)
    for (int j = 0; j <= 40; ++j) {
      const double u = i / 10.0, v = j / 40.0;
      EXPECT_LT(surfaces[0]->Value(u, v).Distance(few->Value(u, v)), 1e-12);
      EXPECT_LT(surfaces[1]->Value(u, v).Distance(many->Value(u, v)), 1e-12);
    }
}

}  // namespace
}  // namespace airshape::geometry
