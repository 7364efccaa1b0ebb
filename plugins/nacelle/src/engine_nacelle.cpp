#include "engine_nacelle.h"

#include <BRep_Builder.hxx>
#include <Eigen/Geometry>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/model/placement.h"
#include "nacelle_cowl.h"

namespace airshape::nacelle {

namespace {

const schema::EnginePositionType& placementNamed(const Configuration& configuration, const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  auto search = [&](const auto& models) -> const schema::EnginePositionType* {
    for (const auto& model : models)
      if (model.engines)
        for (const auto& engine : model.engines->engine)
          if (engine.uID == uid) return &engine;
    return nullptr;
  };
  if (vehicles && vehicles->aircraft)
    if (const auto* found = search(vehicles->aircraft->model)) return *found;
  if (vehicles && vehicles->rotorcraft)
    if (const auto* found = search(vehicles->rotorcraft->model)) return *found;
  throw Error(ErrorCode::InvalidArgument, "no engine placement with uID '" + uid + "'");
}

const schema::EngineType& engineNamed(const Configuration& configuration, const std::string& uid,
                                      const std::string& where) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->engines)
    for (const auto& engine : vehicles->engines->engine)
      if (engine.uID == uid) return engine;
  throw Error(ErrorCode::InvalidModel, "engineUID '" + uid + "' names no engine", {}, where);
}

}  // namespace

NamedShape engineNacelle(const Configuration& configuration, const std::string& placementUid) {
  const schema::EnginePositionType& placement = placementNamed(configuration, placementUid);
  const schema::EngineType& engine = engineNamed(configuration, placement.engineUID, placement.xpath + "/engineUID");
  if (!engine.nacelle) throw NoShape("engine '" + engine.uID + "' has no nacelle: no shape", engine.xpath);
  const schema::EngineNacelleType& nacelle = *engine.nacelle;
  if (!nacelle.fanCowl) throw NoShape("the nacelle has no fan cowl: no shape", nacelle.xpath);
  BRep_Builder builder;
  TopoDS_Compound compound;
  builder.MakeCompound(compound);
  NamedShape nacelleShape;
  int parts = 0;
  auto add = [&](const TopoDS_Shape& solid, const std::string& name) {
    builder.Add(compound, solid);
    nacelleShape.shape = solid;
    ++parts;
    for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next())
      nacelleShape.faces.emplace_back(placementUid + "/" + name, TopoDS::Face(face.Current()));
  };
  add(cowlSolid(configuration, *nacelle.fanCowl), "fan cowl");
  if (nacelle.coreCowl) add(cowlSolid(configuration, *nacelle.coreCowl), "core cowl");
  if (nacelle.centerCowl) add(centerCowlSolid(configuration, *nacelle.centerCowl), "centre cowl");
  // One cowl is its solid itself (CAD formats name solids, not compounds); more, a compound.
  if (parts > 1) nacelleShape.shape = compound;
  return transformedNamedShape(nacelleShape, model::componentTransform(configuration, placementUid));
}

}  // namespace airshape::nacelle
