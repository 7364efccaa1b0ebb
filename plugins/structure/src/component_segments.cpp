#include "component_segments.h"

#include "airshape/configuration.h"
#include "airshape/model/primary_model.h"

namespace airshape::structure {

std::vector<WingComponentSegment> everyComponentSegment(const Configuration& configuration) {
  std::vector<WingComponentSegment> all;
  for (const model::ModelComponents& model : model::everyModel(configuration))
    for (const schema::WingType* wing : model.wings) {
      if (!wing->componentSegments) continue;
      for (const auto& componentSegment : wing->componentSegments->componentSegment)
        all.push_back({wing, &componentSegment});
    }
  return all;
}

}  // namespace airshape::structure
