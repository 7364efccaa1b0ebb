#include "ducts.h"

#include <algorithm>

#include <BRepBndLib.hxx>
#include <Bnd_Box.hxx>
#include <gp_Trsf.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/fused_shape.h"
#include "airshape/model/symmetry.h"

namespace airshape::fuselage {

namespace {

/// Every duct of every aircraft model.
std::vector<const schema::DuctType*> everyDuct(const Configuration& configuration) {
  std::vector<const schema::DuctType*> ducts;
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->aircraft)
    for (const auto& model : vehicles->aircraft->model)
      if (model.ducts)
        for (const auto& duct : model.ducts->duct) ducts.push_back(&duct);
  return ducts;
}

}  // namespace

const schema::DuctType* ductNamed(const Configuration& configuration, const std::string& uid) {
  for (const schema::DuctType* duct : everyDuct(configuration))
    if (duct->uID == uid) return duct;
  return nullptr;
}

const schema::DuctAssemblyType& ductAssemblyNamed(const Configuration& configuration, const std::string& uid) {
  const auto& vehicles = configuration.cpacs().vehicles;
  if (vehicles && vehicles->aircraft)
    for (const auto& model : vehicles->aircraft->model)
      if (model.ducts)
        for (const auto& assembly : model.ducts->ductAssembly)
          if (assembly.uID == uid) return assembly;
  throw Error(ErrorCode::InvalidArgument, "no duct or duct assembly with uID '" + uid + "'");
}

NamedShape ductAssemblySolid(const Configuration& configuration, const schema::DuctAssemblyType& assembly) {
  std::vector<const NamedShape*> ducts;
  if (assembly.ductUIDs)
    for (const std::string& uid : assembly.ductUIDs->uID) {
      if (ductNamed(configuration, uid) == nullptr)
        throw Error(ErrorCode::InvalidModel, "'" + uid + "' names no duct", {}, assembly.xpath + "/ductUIDs");
      ducts.push_back(&configuration.shapes().namedShapeOf(configuration, uid));
      if (model::resolvedSymmetry(configuration, uid) != "none")
        ducts.push_back(&configuration.shapes().mirroredShapeOf(configuration, uid));
    }
  if (ducts.empty()) throw NoShape("the duct assembly names no ducts: no shape", assembly.xpath);
  // One duct is copied: an export names the faces of each component, which two components
  // sharing faces would confuse.
  if (ducts.size() == 1) return transformedNamedShape(*ducts.front(), gp_Trsf());
  return fuseNamedShapes(ducts);
}

const schema::DuctType& ductHolding(const Configuration& configuration, const std::string& segmentUid) {
  for (const schema::DuctType* duct : everyDuct(configuration))
    if (duct->segments)
      for (const auto& segment : duct->segments->segment)
        if (segment.uID == segmentUid) return *duct;
  throw Error(ErrorCode::InvalidArgument, "no duct segment with uID '" + segmentUid + "'");
}

namespace {

/// Whether an assembly's excludeObjectUIDs names the component.
bool excludes(const schema::DuctAssemblyType& assembly, const std::string& uid) {
  if (!assembly.excludeObjectUIDs) return false;
  const std::vector<std::string>& excluded = assembly.excludeObjectUIDs->uID;
  return std::find(excluded.begin(), excluded.end(), uid) != excluded.end();
}

Bnd_Box boxOf(const TopoDS_Shape& shape) {
  Bnd_Box box;
  BRepBndLib::Add(shape, box);
  return box;
}

}  // namespace

std::vector<NamedShape> ductCutOutsOf(const Configuration& configuration, const std::string& uid) {
  // Ducts cut wings and fuselages (as the reference library applies them), nothing else.
  const graph::Component& component = configuration.components().named(uid);
  if (component.nodeType != "wing" && component.nodeType != "fuselage") return {};
  const auto& vehicles = configuration.cpacs().vehicles;
  if (!vehicles || !vehicles->aircraft || component.model >= vehicles->aircraft->model.size()) return {};
  const auto& ducts = vehicles->aircraft->model[component.model].ducts;
  if (!ducts) return {};
  const Bnd_Box reach = boxOf(configuration.shapes().cleanNamedShapeOf(configuration, uid).shape);
  std::vector<NamedShape> cutOuts;
  for (const schema::DuctAssemblyType& assembly : ducts->ductAssembly) {
    if (excludes(assembly, uid) || !assembly.ductUIDs || assembly.ductUIDs->uID.empty()) continue;
    const NamedShape& solid = configuration.shapes().namedShapeOf(configuration, assembly.uID);
    if (!boxOf(solid.shape).IsOut(reach)) cutOuts.push_back(solid);
  }
  return cutOuts;
}

}  // namespace airshape::fuselage
