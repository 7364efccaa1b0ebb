#include "fuselage_frame.h"

#include <Eigen/Geometry>
#include <Eigen/SVD>

#include <BRepBndLib.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepGProp.hxx>
#include <Bnd_Box.hxx>
#include <GProp_GProps.hxx>
#include <IntCurvesFace_ShapeIntersector.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gp_Lin.hxx>
#include <gp_Pln.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/faces_inside.h"
#include "airshape/model/placement.h"

namespace airshape::structure {

FuselageFrame::FuselageFrame(const Configuration& configuration, const schema::FuselageType& fuselage)
    : FuselageFrame(configuration, fuselage.uID, &fuselage, model::componentTransform(configuration, fuselage.uID)) {}

FuselageFrame::FuselageFrame(const Configuration& configuration, const std::string& hostUid,
                             const schema::FuselageType* body, const model::Transform& toGlobal)
    : configuration_(configuration), body_(body), toGlobal_(toGlobal) {
  const NamedShape& host = configuration.shapes().cleanNamedShapeOf(configuration, hostUid);
  solid_ = host.shape;
  const std::string skin = "/skin";
  for (const auto& [name, face] : host.faces)
    if (name.size() >= skin.size() && name.compare(name.size() - skin.size(), skin.size(), skin) == 0)
      skin_.push_back(face);
  if (skin_.empty())
    for (TopExp_Explorer face(solid_, TopAbs_FACE); face.More(); face.Next())
      skin_.push_back(TopoDS::Face(face.Current()));
  Bnd_Box box;
  BRepBndLib::Add(solid_, box);
  reach_ = std::sqrt(box.SquareExtent());
}

FuselageFrame FuselageFrame::ofHost(const Configuration& configuration, const std::string& hostUid,
                                    const schema::FuselageType* body,
                                    const std::optional<model::Transform>& vesselPlacement) {
  if (vesselPlacement) return FuselageFrame(configuration, hostUid, body, *vesselPlacement);
  return FuselageFrame(configuration, *body);
}

gp_Pnt FuselageFrame::toGlobal(const gp_Pnt& point) const { return model::apply(toGlobal_, point); }

gp_Pnt FuselageFrame::toLocal(const gp_Pnt& point) const { return model::apply(toGlobal_.inverse(), point); }

double FuselageFrame::localReach() const { return reach_ / toGlobal_.linear().jacobiSvd().singularValues().minCoeff(); }

const std::vector<TopoDS_Face>& FuselageFrame::skinFaces() const { return skin_; }

gp_Dir FuselageFrame::toGlobal(const gp_Dir& direction) const {
  const Eigen::Vector3d d = toGlobal_.linear() * Eigen::Vector3d(direction.X(), direction.Y(), direction.Z());
  return gp_Dir(d.x(), d.y(), d.z());
}

std::vector<TopoDS_Face> FuselageFrame::crossSection(const gp_Pnt& origin, const gp_Dir& normal) const {
  const TopoDS_Face plane = BRepBuilderAPI_MakeFace(gp_Pln(origin, normal), -reach_, reach_, -reach_, reach_);
  return geometry::facesInside(plane, solid_);
}

TopoDS_Face FuselageFrame::sectionFace(const std::string& sectionUid, const std::string& where) const {
  if (body_ == nullptr)
    throw Error(ErrorCode::InvalidModel, "the vessel has no sections to place on (it is given by design parameters)",
                {}, where);
  auto sectionOf = [&](const std::string& elementUid) -> std::string {
    if (body_->sections)
      for (const auto& section : body_->sections->section)
        if (section.elements)
          for (const auto& element : section.elements->element)
            if (element.uID == elementUid) return section.uID;
    return {};
  };
  if (body_->segments)
    for (const auto& segment : body_->segments->segment) {
      const bool front = sectionOf(segment.fromElementUID) == sectionUid;
      if (!front && sectionOf(segment.toElementUID) != sectionUid) continue;
      const NamedShape& solid = configuration_.shapes().namedShapeOf(configuration_, segment.uID);
      const std::string name = segment.uID + (front ? "/front" : "/rear");
      for (const auto& [faceName, face] : solid.faces)
        if (faceName == name) return face;
    }
  throw Error(ErrorCode::InvalidModel, "fuselageSectionUID '" + sectionUid + "' names no section a segment meets", {},
              where);
}

double FuselageFrame::positionX(const schema::StringerFramePositionType& position) const {
  // Every use of a position asks for its station first: its other numbers are checked here too.
  model::finite(position.referenceY, position.xpath + "/referenceY");
  model::finite(position.referenceZ, position.xpath + "/referenceZ");
  model::finite(position.referenceAngle, position.xpath + "/referenceAngle");
  if (position.positionX) return model::finite(*position.positionX, position.xpath + "/positionX");
  const std::string where = position.xpath + "/sectionElementUID";
  const std::string& uid = position.sectionElementUID.value_or("");
  auto centreX = [&](const std::string& sectionUid) {
    GProp_GProps area;
    BRepGProp::SurfaceProperties(sectionFace(sectionUid, where), area);
    return toLocal(area.CentreOfMass()).X();
  };
  if (body_ != nullptr && body_->sections)
    for (const auto& section : body_->sections->section) {
      if (section.elements)
        for (const auto& element : section.elements->element)
          if (element.uID == uid) return centreX(section.uID);
      if (section.uID == uid) {
        configuration_.warnAboutGeometry(
            {Problem::Severity::Warning, where, "names a section, not a section element: read as its section's"});
        return centreX(section.uID);
      }
    }
  throw Error(ErrorCode::InvalidModel, "sectionElementUID '" + uid + "' names no section element of the body", {},
              where);
}

const schema::StringerFramePositionType* FuselageFrame::offFirstStation(const schema::FrameType& frame) const {
  if (frame.framePosition.size() == 0) return nullptr;
  const double x = positionX(frame.framePosition[0]);
  for (const schema::StringerFramePositionType& position : frame.framePosition)
    if (std::abs(positionX(position) - x) > 1e-9 * std::max(1.0, std::abs(x))) return &position;
  return nullptr;
}

double FuselageFrame::stationX(const schema::FrameType& frame) const {
  if (frame.framePosition.size() == 0)
    throw Error(ErrorCode::InvalidModel, "the frame has no frame position", {}, frame.xpath);
  if (const auto* off = offFirstStation(frame))
    throw Error(ErrorCode::NotImplemented,
                "the frame's positions lie at different stations (a riffled frame): it has no plane station", {},
                off->xpath);
  return positionX(frame.framePosition[0]);
}

gp_Pln FuselageFrame::station(const schema::FrameType& frame) const {
  const schema::StringerFramePositionType& position = frame.framePosition[0];
  return gp_Pln(toGlobal(gp_Pnt(stationX(frame), position.referenceY, position.referenceZ)), toGlobal(gp_Dir(1, 0, 0)));
}

gp_Pnt FuselageFrame::skinAhead(const gp_Pnt& from, const gp_Dir& direction, const std::string& where) const {
  // Loading the faces into an intersector costs far more than a line (a riffled frame asks for
  // three lines a pair of positions): loaded once.
  if (!skinIntersector_) {
    skinIntersector_ = std::make_shared<IntCurvesFace_ShapeIntersector>();
    skinIntersector_->Load(solid_, 1e-7);
  }
  IntCurvesFace_ShapeIntersector& intersector = *skinIntersector_;
  intersector.Perform(gp_Lin(from, direction), 1e-9, reach_);
  if (!intersector.IsDone() || intersector.NbPnt() == 0)
    throw Error(ErrorCode::InvalidModel, "the line from the element does not reach the fuselage's skin", {}, where);
  intersector.SortResult();
  return intersector.Pnt(1);
}

gp_Pnt FuselageFrame::alongXOnto(const TopoDS_Shape& shape, const gp_Pnt& point, const std::string& where) const {
  IntCurvesFace_ShapeIntersector intersector;
  intersector.Load(shape, 1e-7);
  intersector.Perform(gp_Lin(point, toGlobal(gp_Dir(1, 0, 0))), -reach_, reach_);
  if (!intersector.IsDone() || intersector.NbPnt() != 1)
    throw Error(ErrorCode::InvalidModel,
                "the line along the fuselage's x axis through (y, z) meets the referenced element " +
                    std::to_string(intersector.IsDone() ? intersector.NbPnt() : 0) + " times, not once",
                {}, where);
  return intersector.Pnt(1);
}

}  // namespace airshape::structure
