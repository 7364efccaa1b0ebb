#pragma once

#include <vector>

#include <Geom_BSplineCurve.hxx>

namespace airshape::geometry {

/// One B-spline curve made of pieces that follow each other end to end, in parameter as
/// in space: each piece starts where the previous one ends and its parameter range starts
/// where the previous one's ends. Degrees are raised to the highest; the joins become knots
/// of full multiplicity (C0), so every piece keeps its shape and parametrisation exactly.
Handle(Geom_BSplineCurve) concatenateCurves(std::vector<Handle(Geom_BSplineCurve)> pieces);

}  // namespace airshape::geometry
