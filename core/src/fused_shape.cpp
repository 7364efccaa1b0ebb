#include "airshape/fused_shape.h"

#include <BRepAlgoAPI_Cut.hxx>
#include <BRepAlgoAPI_Fuse.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <TopTools_ListOfShape.hxx>

#include "airshape/error.h"

namespace airshape {

NamedShape fuseNamedShapes(const std::vector<const NamedShape*>& shapes) {
  if (shapes.empty()) throw Error(ErrorCode::InvalidArgument, "nothing to fuse");
  if (shapes.size() == 1) return *shapes.front();
  TopTools_ListOfShape arguments, tools;
  arguments.Append(shapes.front()->shape);
  for (std::size_t i = 1; i < shapes.size(); ++i) tools.Append(shapes[i]->shape);
  BRepAlgoAPI_Fuse fuse;
  fuse.SetArguments(arguments);
  fuse.SetTools(tools);
  fuse.SetRunParallel(true);
  fuse.Build();
  if (!fuse.IsDone() || fuse.HasErrors())
    throw Error(ErrorCode::InvalidModel, "the Boolean union of the components failed");
  NamedShape result = namedBooleanResult(fuse, shapes);
  if (!BRepCheck_Analyzer(result.shape).IsValid())
    throw Error(ErrorCode::InvalidModel, "the Boolean union of the components is not a valid shape (BRepCheck)");
  return result;
}

NamedShape cutNamedShape(const NamedShape& argument, const NamedShape& tool) {
  BRepAlgoAPI_Cut cut;
  TopTools_ListOfShape arguments, tools;
  arguments.Append(argument.shape);
  tools.Append(tool.shape);
  cut.SetArguments(arguments);
  cut.SetTools(tools);
  cut.SetRunParallel(true);
  // Oriented boxes pass over more of the pairs of a cutter's plane faces and a lifting surface's skins
  // that cannot meet (docs/performance.md, CPACS_30_aircraft_flaps.xml).
  cut.SetUseOBB(true);
  cut.Build();
  if (!cut.IsDone() || cut.HasErrors()) throw Error(ErrorCode::InvalidModel, "the Boolean cut failed");
  return namedBooleanResult(cut, {&argument, &tool});
}

}  // namespace airshape
