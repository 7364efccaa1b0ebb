#include "airshape/model/approximation_settings.h"

#include <cmath>
#include <sstream>

#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "airshape/xml/text.h"

namespace airshape::model {

namespace {

/// A count or index given as a number: whole, or an error naming the node.
int wholeNumber(double value, const std::string& xpath) {
  if (value != std::floor(value) || std::abs(value) > 1e9)
    throw Error(ErrorCode::InvalidModel, (std::ostringstream() << "not a whole number: " << value).str(), {}, xpath);
  return static_cast<int>(value);
}

/// How the settings' errorComputationMethod measures a fit (RMSE when not given).
geometry::FitError fitErrorOf(const xercesc::DOMElement& settings, const std::string& xpath) {
  const std::string method = xml::attribute(settings, "errorComputationMethod");
  if (method.empty() || method == "RMSE") return geometry::FitError::RootMeanSquare;
  if (method == "MaxError") return geometry::FitError::Largest;
  throw Error(ErrorCode::InvalidModel, "errorComputationMethod must be RMSE or MaxError (got '" + method + "')", {},
              xpath);
}

}  // namespace

ApproximationSettings approximationSettings(const xercesc::DOMElement& settings, const std::string& xpath,
                                            int pointCount) {
  const auto* count = xml::firstChild(settings, "controlPointNumber");
  if (!count)
    throw Error(ErrorCode::InvalidModel,
                "approximationSettings need a controlPointNumber (a maximumError alone is not supported)", {}, xpath);
  ApproximationSettings request;
  const std::string countPath = xpath + "/controlPointNumber";
  request.poles = wholeNumber(parseVector(xml::text(*count), countPath).at(0), countPath);
  if (request.poles < 4 || request.poles > pointCount)
    throw Error(ErrorCode::InvalidModel,
                "controlPointNumber must lie in [4, number of points] (got " + std::to_string(request.poles) + " for " +
                    std::to_string(pointCount) + " points)",
                {}, countPath);
  request.measure = fitErrorOf(settings, xpath);
  if (const auto* indices = xml::firstChild(settings, "interpolatedPointsIndices"))
    for (double given : parseVector(xml::text(*indices), xpath + "/interpolatedPointsIndices")) {
      const int index = wholeNumber(given, xpath + "/interpolatedPointsIndices") - 1;  // given 1-based
      if (index < 0 || index >= pointCount)
        throw Error(ErrorCode::InvalidModel, "interpolatedPointsIndices must lie in [1, number of points]", {}, xpath);
      request.interpolated.push_back(index);
    }
  return request;
}

}  // namespace airshape::model
