#include "device_geometry.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <memory>
#include <optional>
#include <sstream>
#include <string>

#include <BRepAlgoAPI_Common.hxx>
#include <BRepCheck_Analyzer.hxx>
#include <BRepLib.hxx>
#include <BRep_Builder.hxx>
#include <BRep_Tool.hxx>
#include <Eigen/Geometry>
#include <Geom_Line.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedDataMapOfShapeListOfShape.hxx>
#include <TopTools_ListOfShape.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <gp_Lin.hxx>
#include <gp_Pnt2d.hxx>
#include <gp_Vec2d.hxx>

#include "airshape/configuration.h"
#include "airshape/error.h"
#include "airshape/geometry/ruled_sections.h"
#include "airshape/model/placement.h"
#include "airshape/wing/wing_list.h"
#include "device_from_skins.h"
#include "hinge_motion.h"
#include "line_crossings.h"
#include "outline_closing.h"

namespace airshape::controlsurfaces {

namespace {

using Surface = wing::WingServices::Surface;

}  // namespace

DeviceGeometry::DeviceGeometry(const Configuration& configuration, const wing::WingServices& wing, Device device)
    : configuration_(configuration), wing_(wing), device_(std::move(device)) {
  if (!device_.hasOuterShape)
    throw Error(ErrorCode::InvalidModel, "the device has no outerShape with an inner and an outer border", {},
                device_.xpath);
  for (const BorderDefinition* border : {&device_.innerBorder, &device_.outerBorder})
    if (!border->missing.empty())
      throw Error(ErrorCode::InvalidModel, "the border has no " + border->missing, {}, border->xpath);
}

double DeviceGeometry::componentSegmentEta(const RelativeCoordinate& eta, const std::string& xpath) const {
  const std::string& cs = device_.componentSegmentUid;
  if (eta.referenceUid.empty() || eta.referenceUid == cs) return eta.value;
  try {
    return wing_.componentSegmentEta(configuration_, cs, eta.referenceUid, eta.value);
  } catch (const Error& notConvertible) {
    // Files often refer to another component segment or to the device itself (copied from
    // elsewhere); the reference library reads such an eta as the device's own component
    // segment's, and so does this plugin, saying so.
    configuration_.warnAboutGeometry({Problem::Severity::Warning, xpath,
                                      "referenceUID '" + eta.referenceUid + "' is neither component segment '" + cs +
                                          "' nor one of its wing segments; eta read as one of '" + cs + "'"});
    return eta.value;
  }
}

std::pair<double, double> DeviceGeometry::componentSegmentCoordinates(double eta, double xsi) const {
  const BorderDefinition &inner = device_.innerBorder, &outer = device_.outerBorder;
  const auto between = [](double a, double b, double share) { return a + share * (b - a); };
  const double innerEta = between(componentSegmentEta(inner.etaLE, inner.xpath + "/etaLE"),
                                  componentSegmentEta(inner.etaTE, inner.xpath + "/etaTE"), xsi);
  const double outerEta = between(componentSegmentEta(outer.etaLE, outer.xpath + "/etaLE"),
                                  componentSegmentEta(outer.etaTE, outer.xpath + "/etaTE"), xsi);
  const double innerXsi = between(inner.xsiLE, inner.xsiTE, xsi), outerXsi = between(outer.xsiLE, outer.xsiTE, xsi);
  return {between(innerEta, outerEta, eta), between(innerXsi, outerXsi, eta)};
}

gp_Pnt DeviceGeometry::ownChordPoint(double eta, double xsi) const {
  const BorderDefinition &inner = device_.innerBorder, &outer = device_.outerBorder;
  // An edge on the wing's own edge follows the wing; one within the wing runs straight.
  const auto edgePoint = [&](bool leading) {
    const RelativeCoordinate &innerEta = leading ? inner.etaLE : inner.etaTE,
                             &outerEta = leading ? outer.etaLE : outer.etaTE;
    const double innerXsi = leading ? inner.xsiLE : inner.xsiTE, outerXsi = leading ? outer.xsiLE : outer.xsiTE;
    const bool onWingEdge = (innerXsi == 0.0 && outerXsi == 0.0) || (innerXsi == 1.0 && outerXsi == 1.0);
    if (!onWingEdge) {
      const gp_Pnt innerPoint = chordPoint(innerEta, innerXsi, inner.xpath);
      return innerPoint.Translated(eta * gp_Vec(innerPoint, chordPoint(outerEta, outerXsi, outer.xpath)));
    }
    const double innerCsEta = componentSegmentEta(innerEta, inner.xpath);
    const double csEta = innerCsEta + eta * (componentSegmentEta(outerEta, outer.xpath) - innerCsEta);
    return wing_.componentSegmentPoint(configuration_, device_.componentSegmentUid, csEta, innerXsi, Surface::Chord);
  };
  const gp_Pnt leadingEdge = edgePoint(true), trailingEdge = edgePoint(false);
  return leadingEdge.Translated(xsi * gp_Vec(leadingEdge, trailingEdge));
}

gp_Pnt DeviceGeometry::chordPoint(const RelativeCoordinate& eta, double xsi, const std::string& xpath) const {
  return wing_.componentSegmentPoint(configuration_, device_.componentSegmentUid, componentSegmentEta(eta, xpath), xsi,
                                     Surface::Chord);
}

BorderPlane DeviceGeometry::borderPlaneOf(const BorderDefinition& border) const {
  model::fraction(border.etaLE.value, border.xpath + "/etaLE/eta");
  model::fraction(border.etaTE.value, border.xpath + "/etaTE/eta");
  model::fraction(border.xsiLE, border.xpath + "/xsiLE/xsi");
  model::fraction(border.xsiTE, border.xpath + "/xsiTE/xsi");
  try {
    return BorderPlane(chordPoint(border.etaLE, border.xsiLE, border.xpath + "/etaLE"),
                       chordPoint(border.etaTE, border.xsiTE, border.xpath + "/etaTE"), upward());
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, border.xpath);
  }
}

gp_Vec DeviceGeometry::upward() const {
  // The component segment's inner chord crossed with its inner leading edge.
  const std::string& cs = device_.componentSegmentUid;
  const gp_Pnt innerFront = wing_.componentSegmentPoint(configuration_, cs, 0.0, 0.0, Surface::Chord);
  return gp_Vec(innerFront, wing_.componentSegmentPoint(configuration_, cs, 0.0, 1.0, Surface::Chord))
      .Crossed(gp_Vec(innerFront, wing_.componentSegmentPoint(configuration_, cs, 1.0, 0.0, Surface::Chord)));
}

BorderOutline DeviceGeometry::borderOutlineOf(const BorderDefinition& border, const BorderPlane& plane,
                                              LineCrossings& wing) const {
  try {
    const TopoDS_Wire airfoil = border.nose == BorderDefinition::Nose::Airfoil
                                    ? wing_.airfoilWire(configuration_, border.airfoilUid)
                                    : TopoDS_Wire();
    return borderOutline(border, plane, wing, airfoil);
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;
    throw Error(error.code(), error.message(), {}, border.xpath);
  }
}

std::vector<TopoDS_Wire> DeviceGeometry::intermediateWires(const BorderPlane& inner, const BorderPlane& outer,
                                                           LineCrossings& wing) const {
  if (device_.intermediateAirfoils.empty()) return {};
  if (device_.innerBorder.nose != BorderDefinition::Nose::Airfoil ||
      device_.outerBorder.nose != BorderDefinition::Nose::Airfoil) {
    configuration_.warnAboutGeometry({Problem::Severity::Warning, device_.xpath + "/outerShape/intermediateAirfoils",
                                      "intermediate airfoils shape a device whose borders give airfoils; ignored"});
    return {};
  }
  const double innerEta = componentSegmentEta(device_.innerBorder.etaLE, device_.innerBorder.xpath + "/etaLE");
  const double outerEta = componentSegmentEta(device_.outerBorder.etaLE, device_.outerBorder.xpath + "/etaLE");
  std::vector<std::pair<double, TopoDS_Wire>> placed;  // by their share of the way inner -> outer
  for (const IntermediateAirfoil& airfoil : device_.intermediateAirfoils) {
    const double share = (componentSegmentEta(airfoil.eta, airfoil.xpath + "/eta") - innerEta) / (outerEta - innerEta);
    if (!(share > 0.0 && share < 1.0))
      throw Error(ErrorCode::InvalidModel, "eta lies outside the device's leading edge between its borders", {},
                  airfoil.xpath + "/eta");
    if (std::abs(airfoil.rotX - 90.0) > 1e-9 || std::abs(airfoil.rotZ - 90.0) > 1e-9)
      configuration_.warnAboutGeometry({Problem::Severity::Warning, airfoil.xpath,
                                        "rotX and rotZ other than 90 degrees are not applied: the airfoil is "
                                        "placed between the device's leading and trailing edge"});
    auto between = [share](const gp_Pnt& a, const gp_Pnt& b) { return gp_Pnt(a.XYZ() + share * (b.XYZ() - a.XYZ())); };
    const BorderPlane plane(between(inner.origin, outer.origin),
                            between(inner.at(inner.chord, 0.0), outer.at(outer.chord, 0.0)), upward());
    BorderDefinition section;
    section.xpath = airfoil.xpath;
    section.nose = BorderDefinition::Nose::Airfoil;
    section.airfoilUid = airfoil.airfoilUid;
    section.airfoilScaleZ = airfoil.scaleZ;
    placed.emplace_back(share, closedOutlines({borderOutlineOf(section, plane, wing)}).front());
  }
  std::sort(placed.begin(), placed.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<TopoDS_Wire> wires;
  for (const auto& entry : placed) wires.push_back(entry.second);
  return wires;
}

namespace {

/// What the faces of the ruled solid between a device's borders become of the device.
std::string cutterFaceName(const Device& device) {
  if (device.innerBorder.nose == BorderDefinition::Nose::Airfoil) return "skin";
  switch (device.kind) {
    case Device::Kind::LeadingEdge:
      return "trailing edge";
    case Device::Kind::Spoiler:
      return "lower";
    case Device::Kind::TrailingEdge:
      break;
  }
  return "leading edge";
}

/// What a face of the wing becomes of a device cut out of it, by the last part of its name.
std::string deviceFaceName(const std::string& wingFaceName) {
  const std::string what = wingFaceName.substr(wingFaceName.rfind('/') + 1);
  if (what == "trailingEdge") return "trailing edge";
  if (what == "root" || what == "inner") return "inner side";
  if (what == "tip" || what == "outer") return "outer side";
  return what;  // upper, lower, skin
}

}  // namespace

NamedShape DeviceGeometry::cutter() const {
  // Cached: the device at rest, its cut-out and the structure inside it all start from it.
  return *configuration_.cache().obtain<NamedShape>("device-cutter:" + device_.uid,
                                                    [&] { return std::make_shared<const NamedShape>(ruledCutter()); });
}

void DeviceGeometry::checkBordersApart() const {
  // Each border's chord from its leading- to its trailing-edge point, as (eta, xsi).
  const auto chordOf = [&](const BorderDefinition& border) {
    return std::array<gp_Pnt2d, 2>{gp_Pnt2d(componentSegmentEta(border.etaLE, border.xpath + "/etaLE"), border.xsiLE),
                                   gp_Pnt2d(componentSegmentEta(border.etaTE, border.xpath + "/etaTE"), border.xsiTE)};
  };
  const auto [a, b] = chordOf(device_.innerBorder);
  const auto [c, d] = chordOf(device_.outerBorder);
  const auto side = [](const gp_Pnt2d& from, const gp_Pnt2d& to, const gp_Pnt2d& p) {
    return gp_Vec2d(from, to).Crossed(gp_Vec2d(from, p));
  };
  const double sideC = side(a, b, c), sideD = side(a, b, d), sideA = side(c, d, a), sideB = side(c, d, b);
  if (!(sideC * sideD < 0.0 && sideA * sideB < 0.0)) return;  // touching at an end is a pointed device
  const gp_Pnt2d crossing = a.Translated(sideA / (sideA - sideB) * gp_Vec2d(a, b));
  std::ostringstream text;
  text << "the inner and the outer border cross inside the wing (at component segment eta " << std::setprecision(4)
       << crossing.X() << ", xsi " << crossing.Y() << "): the device between them would fold through itself";
  throw Error(ErrorCode::InvalidModel, text.str(), {}, device_.xpath + "/outerShape");
}

DeviceGeometry::Outlines DeviceGeometry::outlines() const {
  return *configuration_.cache().obtain<Outlines>("device-outlines:" + device_.uid, [&] {
    checkBordersApart();
    const BorderPlane innerPlane = borderPlaneOf(device_.innerBorder), outerPlane = borderPlaneOf(device_.outerBorder);
    const double size = innerPlane.chord + outerPlane.chord + innerPlane.origin.Distance(outerPlane.origin);
    LineCrossings wing(wing_.cleanSolid(configuration_, device_.wingUid));
    const std::vector<TopoDS_Wire> borders = closedOutlines({borderOutlineOf(device_.innerBorder, innerPlane, wing),
                                                             borderOutlineOf(device_.outerBorder, outerPlane, wing)});
    return std::make_shared<const Outlines>(
        Outlines{borders[0], borders[1], intermediateWires(innerPlane, outerPlane, wing), size});
  });
}

NamedShape DeviceGeometry::ruledCutter() const {
  const Outlines outline = outlines();
  std::vector<TopoDS_Wire> wires{outline.outer};
  wires.insert(wires.end(), outline.between.rbegin(), outline.between.rend());
  wires.push_back(outline.inner);
  const geometry::RuledSections loft = geometry::ruledThroughSections(wires);
  if (loft.solid.IsNull())
    throw Error(ErrorCode::InvalidModel, "no solid joins the device's inner and outer border", {},
                device_.xpath + "/outerShape");
  NamedShape cutter{loft.solid, {}};
  for (TopExp_Explorer face(cutter.shape, TopAbs_FACE); face.More(); face.Next()) {
    const std::string name = face.Current().IsSame(loft.firstCap)  ? "outer side"
                             : face.Current().IsSame(loft.lastCap) ? "inner side"
                                                                   : cutterFaceName(device_);
    cutter.faces.emplace_back(device_.uid + "/" + name, TopoDS::Face(face.Current()));
  }
  return cutter;
}

namespace {

/// The face of a ruled cutter ruled between its borders' curved edges (a rounded nose, a
/// hollow back): the face beside the curved edge of its inner side; null where there is none.
TopoDS_Face shapedSideOf(const NamedShape& cutter, const std::string& innerSideName) {
  TopTools_IndexedDataMapOfShapeListOfShape facesOfEdges;
  TopExp::MapShapesAndAncestors(cutter.shape, TopAbs_EDGE, TopAbs_FACE, facesOfEdges);
  for (const auto& [name, face] : cutter.faces) {
    if (name != innerSideName) continue;
    for (TopExp_Explorer edge(face, TopAbs_EDGE); edge.More(); edge.Next()) {
      double first = 0.0, last = 0.0;
      const Handle(Geom_Curve) curve = BRep_Tool::Curve(TopoDS::Edge(edge.Current()), first, last);
      if (curve.IsNull() || curve->DynamicType() == STANDARD_TYPE(Geom_Line)) continue;
      for (const TopoDS_Shape& beside : facesOfEdges.FindFromKey(edge.Current()))
        if (!beside.IsSame(face)) return TopoDS::Face(beside);
    }
  }
  return {};
}

}  // namespace

std::optional<NamedShape> DeviceGeometry::fromWingSkins() const {
  using Nose = BorderDefinition::Nose;
  const Nose nose = device_.innerBorder.nose;
  if (device_.outerBorder.nose != nose) return std::nullopt;
  OutlineKind kind = OutlineKind::Panel;
  if (nose == Nose::Straight) {
    // A cut at the wing's own leading edge only touches the skins there: the whole chord.
    const bool atLeadingEdge = device_.innerBorder.xsiLE <= 0.0, outerAtLeadingEdge = device_.outerBorder.xsiLE <= 0.0;
    if (atLeadingEdge != outerAtLeadingEdge) return std::nullopt;
    kind = atLeadingEdge ? OutlineKind::WholeChord : OutlineKind::Aft;
  } else if (nose == Nose::LeadingEdgeShape) {
    kind = OutlineKind::Aft;
  } else if (nose == Nose::StraightBack || nose == Nose::InnerShape) {
    kind = OutlineKind::Ahead;
  } else if (nose != Nose::Panel) {
    return std::nullopt;
  }
  // The ruled cutter itself is needed for a shaped side and for the pieces of the skins round
  // a leading edge; straight outlines aft of the leading edge do without it.
  const bool shaped = nose == Nose::LeadingEdgeShape || nose == Nose::InnerShape;
  const NamedShape ruled = shaped || kind == OutlineKind::Ahead ? cutter() : NamedShape();
  const TopoDS_Face shapedSide = shaped ? shapedSideOf(ruled, device_.uid + "/inner side") : TopoDS_Face();
  if (shaped && shapedSide.IsNull()) return std::nullopt;
  const std::string& cs = device_.componentSegmentUid;
  WingSkins skins{wing_.componentSegmentSkin(configuration_, cs, Surface::Upper),
                  wing_.componentSegmentSkin(configuration_, cs, Surface::Lower),
                  {}};
  if (skins.upper.IsSame(skins.lower)) return std::nullopt;  // one face for both: not split along lines
  if (kind == OutlineKind::Aft || kind == OutlineKind::WholeChord) {
    TopoDS_Compound trailingEdge;
    BRep_Builder builder;
    builder.MakeCompound(trailingEdge);
    bool any = false;
    for (const auto& [name, face] : configuration_.shapes().cleanNamedShapeOf(configuration_, device_.wingUid).faces)
      if (name.size() > 13 && name.compare(name.size() - 13, 13, "/trailingEdge") == 0) {
        builder.Add(trailingEdge, face);
        any = true;
      }
    if (any) skins.trailingEdge = trailingEdge;
  }
  const Outlines borders = outlines();
  return deviceFromSkins(skins, kind, borders.inner, borders.outer, ruled.shape, shapedSide,
                         {device_.uid + "/", cutterFaceName(device_)}, 1e-8 * borders.size);
}

namespace {

/// The Boolean common of a wing and a device's cutter, with OCCT's fuzzy tolerance `fuzzy`
/// (none at 0). Most of the time goes into intersecting the cutter's faces and edges with the
/// wing's (docs/performance.md): the pairs are intersected on every core.
std::unique_ptr<BRepAlgoAPI_Common> commonOf(const TopoDS_Shape& wing, const TopoDS_Shape& cutter, double fuzzy) {
  auto common = std::make_unique<BRepAlgoAPI_Common>();
  TopTools_ListOfShape arguments, tools;
  arguments.Append(wing);
  tools.Append(cutter);
  common->SetArguments(arguments);
  common->SetTools(tools);
  common->SetRunParallel(true);
  if (fuzzy > 0.0) common->SetFuzzyValue(fuzzy);
  common->Build();
  return common;
}

/// What is wrong with a Boolean common's result, in words: no solid, a flawed one (as OCCT
/// checks shapes), or a failure; nothing when it is a valid solid.
std::optional<std::string> flawOf(BRepAlgoAPI_Common& common) {
  if (!common.IsDone() || common.HasErrors()) return "failed";
  if (!TopExp_Explorer(common.Shape(), TopAbs_SOLID).More()) return "left faces it could not place and made no solid";
  if (!BRepCheck_Analyzer(common.Shape()).IsValid()) return "made a flawed solid";
  return std::nullopt;
}

}  // namespace

std::unique_ptr<BRepAlgoAPI_Common> DeviceGeometry::cutOutOf(const TopoDS_Shape& wing,
                                                             const TopoDS_Shape& cutter) const {
  // OCCT's exact Boolean may leave faces it cannot place and make no solid, or make a flawed one
  // (a slat's hollow back lofted against a straight one on the example airliner): tried again
  // with its fuzzy tolerance, a millionth and then a hundred-thousandth of the device's size,
  // with a warning; where neither does better, the exact result stands.
  std::unique_ptr<BRepAlgoAPI_Common> common = commonOf(wing, cutter, 0.0);
  const std::optional<std::string> flaw = flawOf(*common);
  if (!flaw) return common;
  for (const double share : {1e-6, 1e-5}) {
    const double fuzzy = share * outlines().size;
    std::unique_ptr<BRepAlgoAPI_Common> retried = commonOf(wing, cutter, fuzzy);
    if (flawOf(*retried)) continue;
    std::ostringstream text;
    text << "cut out of its wing with the Boolean's fuzzy tolerance of " << std::setprecision(2) << fuzzy
         << " m: without it OCCT's Boolean " << *flaw;
    configuration_.warnAboutGeometry({Problem::Severity::Warning, device_.xpath + "/outerShape", text.str()});
    return retried;
  }
  return common;
}

NamedShape DeviceGeometry::atRest() const {
  if (std::optional<NamedShape> direct = fromWingSkins()) return std::move(*direct);
  const NamedShape cut = cutter();
  if (device_.innerBorder.nose == BorderDefinition::Nose::Airfoil) return cut;
  const NamedShape& wing = configuration_.shapes().cleanNamedShapeOf(configuration_, device_.wingUid);
  NamedShape wingFaces{wing.shape, {}};
  for (const auto& [name, face] : wing.faces)
    wingFaces.faces.emplace_back(device_.uid + "/" + deviceFaceName(name), face);
  const std::unique_ptr<BRepAlgoAPI_Common> common = cutOutOf(wing.shape, cut.shape);
  if (!common->IsDone() || common->HasErrors())
    throw Error(ErrorCode::InvalidModel, "the device cannot be cut out of its wing", {}, device_.xpath);
  if (!TopExp_Explorer(common->Shape(), TopAbs_SOLID).More())
    throw Error(ErrorCode::InvalidModel, "the device's outline cuts nothing out of its wing", {},
                device_.xpath + "/outerShape");
  NamedShape shape = namedBooleanResult(*common, {&wingFaces, &cut});
  // Where a border lies in a cap of the wing, the Boolean leaves edges with curves on their
  // faces only; measures and exports need them in space too.
  BRepLib::BuildCurves3d(shape.shape);
  return shape;
}

TopoDS_Shape DeviceGeometry::skinCutOut() const {
  if (!device_.wingCutOut) return {};
  const WingCutOut& cutOut = *device_.wingCutOut;
  if (!cutOut.notApplied.empty()) {
    std::string what;
    for (const std::string& item : cutOut.notApplied) what += (what.empty() ? "" : ", ") + item;
    configuration_.warnAboutGeometry({Problem::Severity::Warning, cutOut.xpath, "not applied: " + what});
  }
  if (!cutOut.skinsKnown || device_.kind == Device::Kind::Spoiler) return {};
  const bool aft = device_.kind == Device::Kind::TrailingEdge;
  // The outline at one end: in the cut-out border's own plane where it gives its etas, else in
  // the device border's; the skins' xsi are component segment xsi at that plane's front.
  LineCrossings wing(wing_.cleanSolid(configuration_, device_.wingUid));
  auto outline = [&](const BorderDefinition& border, const std::optional<RelativeCoordinate>& etaLE,
                     const std::optional<RelativeCoordinate>& etaTE, double upperXsi, double lowerXsi,
                     const std::string& xpath) {
    BorderDefinition end = border;
    if (etaLE) end.etaLE = *etaLE;
    if (etaLE || etaTE) end.etaTE = etaTE ? *etaTE : end.etaLE;
    const BorderPlane plane = borderPlaneOf(end);
    const double eta = componentSegmentEta(end.etaLE, xpath);
    auto share = [&](double xsi) {
      model::fraction(xsi, xpath);
      return gp_Vec(plane.origin,
                    wing_.componentSegmentPoint(configuration_, device_.componentSegmentUid, eta, xsi, Surface::Chord))
                 .Dot(plane.x) /
             plane.chord;
    };
    return skinCutOutOutline(plane, wing, share(upperXsi), share(lowerXsi), aft, xpath);
  };
  const geometry::RuledSections loft =
      geometry::ruledThroughSections(closedOutlines({outline(device_.outerBorder, cutOut.outerEtaLE, cutOut.outerEtaTE,
                                                             cutOut.upperOuter, cutOut.lowerOuter, cutOut.xpath),
                                                     outline(device_.innerBorder, cutOut.innerEtaLE, cutOut.innerEtaTE,
                                                             cutOut.upperInner, cutOut.lowerInner, cutOut.xpath)}));
  if (loft.solid.IsNull())
    throw Error(ErrorCode::InvalidModel, "no solid joins the cut-out's borders", {}, cutOut.xpath);
  return loft.solid;
}

std::pair<double, double> DeviceGeometry::parameterRange() const { return parameterRangeOf(device_); }

gp_Pnt DeviceGeometry::hingePoint(const schema::ControlSurfaceHingePointType& hinge, const BorderDefinition& border,
                                  const char* which, const std::array<LineCrossings*, 2>& skins) const {
  const std::string xpath = device_.xpath + "/path/" + which;
  model::fraction(hinge.hingeXsi, xpath + "/hingeXsi");
  model::fraction(hinge.hingeRelHeight, xpath + "/hingeRelHeight");
  const double eta = componentSegmentEta(border.etaLE, border.xpath + "/etaLE");
  const gp_Pnt onChord =
      wing_.componentSegmentPoint(configuration_, device_.componentSegmentUid, eta, hinge.hingeXsi, Surface::Chord);
  const gp_Vec normal = wing_.midplaneNormal(configuration_, device_.componentSegmentUid, eta);
  // Projected along the normal onto each skin: where the normal meets it, or its nearest point.
  const gp_Lin across(onChord, gp_Dir(normal));
  const std::string& cs = device_.componentSegmentUid;
  const double chord = wing_.componentSegmentPoint(configuration_, cs, eta, 0.0, Surface::Chord)
                           .Distance(wing_.componentSegmentPoint(configuration_, cs, eta, 1.0, Surface::Chord));
  const auto onSkin = [&](LineCrossings& skin) {
    // Meeting the line is cheap; the nearest point (a hinge beyond the skin's edge) is not.
    const std::vector<LineCrossing> hits = skin.of(across, 1e-9 * chord);
    if (hits.empty()) return nearestToLine(skin.shape(), across, 10.0 * chord);
    return std::min_element(
               hits.begin(), hits.end(),
               [](const LineCrossing& a, const LineCrossing& b) { return std::abs(a.along) < std::abs(b.along); })
        ->point;
  };
  const gp_Pnt upper = onSkin(*skins[0]), lower = onSkin(*skins[1]);
  const gp_Pnt between(lower.XYZ() + hinge.hingeRelHeight * (upper.XYZ() - lower.XYZ()));

  // The reference places hinge points by the wing's own transformation only.
  const schema::WingType& wing = wing::wingNamed(configuration_, device_.wingUid);
  gp_Pnt local = model::apply(model::componentTransform(configuration_, device_.wingUid).inverse(), between);
  if (hinge.translation) {
    const schema::PointType& t = *hinge.translation;
    local.Translate(gp_Vec(t.x.value_or(0.0), t.y.value_or(0.0), t.z.value_or(0.0)));
  }
  return model::apply(model::transformationMatrix(wing.transformation ? &*wing.transformation : nullptr), local);
}

gp_Trsf DeviceGeometry::motionAt(double controlParameter) const {
  const auto [first, last] = parameterRange();
  if (!(controlParameter >= std::min(first, last) && controlParameter <= std::max(first, last)))
    throw Error(ErrorCode::InvalidArgument, "control parameter " + std::to_string(controlParameter) +
                                                " lies outside the range [" + std::to_string(std::min(first, last)) +
                                                ", " + std::to_string(std::max(first, last)) + "] of '" + device_.uid +
                                                "'");
  if (!device_.path->innerHingePoint || !device_.path->outerHingePoint)
    throw Error(ErrorCode::InvalidModel, "the path has no inner and outer hinge point", {}, device_.xpath + "/path");
  // The hinge points at rest are found once per configuration; a further deflection is the
  // motion alone.
  using HingeLine = std::pair<gp_Pnt, gp_Pnt>;
  const auto hinge = configuration_.cache().obtain<HingeLine>("device-hinge-line:" + device_.uid, [&] {
    const std::string& cs = device_.componentSegmentUid;
    LineCrossings upper(wing_.componentSegmentSkin(configuration_, cs, Surface::Upper));
    LineCrossings lower(wing_.componentSegmentSkin(configuration_, cs, Surface::Lower));
    return std::make_shared<const HingeLine>(
        hingePoint(*device_.path->innerHingePoint, device_.innerBorder, "innerHingePoint", {&upper, &lower}),
        hingePoint(*device_.path->outerHingePoint, device_.outerBorder, "outerHingePoint", {&upper, &lower}));
  });
  try {
    return hingeMotion(hinge->first, hinge->second, stepValuesAt(*device_.path->steps, controlParameter));
  } catch (const Error& error) {
    if (!error.cpacsPath().empty()) throw;  // a step's value, named already
    throw Error(error.code(), error.message(), {}, device_.xpath + "/path");
  }
}

}  // namespace airshape::controlsurfaces
