#include "step_brep_writer.h"

#include <algorithm>
#include <charconv>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <ostream>
#include <unordered_map>
#include <vector>

#include <BRepTools.hxx>
#include <BRepTools_WireExplorer.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_Circle.hxx>
#include <Geom_ConicalSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_ElementarySurface.hxx>
#include <Geom_Line.hxx>
#include <Geom_Plane.hxx>
#include <Geom_RectangularTrimmedSurface.hxx>
#include <Geom_SphericalSurface.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <Geom_ToroidalSurface.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <NCollection_DataMap.hxx>
#include <TopExp.hxx>
#include <TopExp_Explorer.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <TopTools_ShapeMapHasher.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Iterator.hxx>
#include <TopoDS_Vertex.hxx>
#include <TopoDS_Wire.hxx>

#include "format_writers.h"

namespace airshape::exporting {

namespace {

// ---- what the writer takes ----

Handle(Geom_Surface) basisSurface(const TopoDS_Face& face) {
  Handle(Geom_Surface) surface = BRep_Tool::Surface(face);  // with the face's location applied
  while (auto trimmed = Handle(Geom_RectangularTrimmedSurface)::DownCast(surface)) surface = trimmed->BasisSurface();
  return surface;
}

Handle(Geom_Curve) withoutTrimming(Handle(Geom_Curve) curve) {
  while (auto trimmed = Handle(Geom_TrimmedCurve)::DownCast(curve)) curve = trimmed->BasisCurve();
  return curve;
}

Handle(Geom_Curve) basisCurve(const TopoDS_Edge& edge, double& first, double& last) {
  return withoutTrimming(BRep_Tool::Curve(edge, first, last));  // with the edge's location applied
}

bool writableCurve(const Handle(Geom_Curve) & curve) {
  return !curve.IsNull() && (curve->IsKind(STANDARD_TYPE(Geom_BSplineCurve)) ||
                             curve->IsKind(STANDARD_TYPE(Geom_Line)) || curve->IsKind(STANDARD_TYPE(Geom_Circle)));
}

/// B-spline surfaces, planes, the elementary surfaces STEP has and surfaces of revolution of
/// curves we write.
bool writableSurface(const Handle(Geom_Surface) & surface) {
  if (surface.IsNull()) return false;
  if (auto revolution = Handle(Geom_SurfaceOfRevolution)::DownCast(surface))
    return writableCurve(withoutTrimming(revolution->BasisCurve()));
  return surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface)) || surface->IsKind(STANDARD_TYPE(Geom_Plane)) ||
         surface->IsKind(STANDARD_TYPE(Geom_CylindricalSurface)) ||
         surface->IsKind(STANDARD_TYPE(Geom_ConicalSurface)) || surface->IsKind(STANDARD_TYPE(Geom_SphericalSurface)) ||
         surface->IsKind(STANDARD_TYPE(Geom_ToroidalSurface));
}

bool writableFace(const TopoDS_Face& face) {
  const Handle(Geom_Surface) surface = basisSurface(face);
  if (face.Location().Transformation().IsNegative() || !writableSurface(surface)) return false;
  // A pole (degenerate edge) is left out of its loop, and readers restore it from the edges
  // around it: exactly on B-spline surfaces (lofted noses, to 1e-15 in volume), but a
  // spinner revolved from pole to pole came back 3e-6 off. Such faces go to OCCT's writer.
  const bool polesAllowed = surface->IsKind(STANDARD_TYPE(Geom_BSplineSurface));
  for (TopoDS_Iterator wire(face); wire.More(); wire.Next()) {
    bool anyEdge = false;
    for (TopoDS_Iterator item(wire.Value()); item.More(); item.Next()) {
      const TopoDS_Edge& edge = TopoDS::Edge(item.Value());
      if (BRep_Tool::Degenerated(edge)) {
        if (!polesAllowed) return false;
        continue;
      }
      double first, last;
      if (!writableCurve(basisCurve(edge, first, last))) return false;
      anyEdge = true;
    }
    if (!anyEdge) return false;  // a loop of degenerate edges only (a vertex loop): not ours
  }
  return true;
}

bool writableSolid(const TopoDS_Shape& solid) {
  int shells = 0;
  for (TopoDS_Iterator shell(solid); shell.More(); shell.Next()) {
    if (shell.Value().ShapeType() != TopAbs_SHELL || !BRep_Tool::IsClosed(shell.Value())) return false;
    ++shells;
  }
  if (shells != 1) return false;
  for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next())
    if (!writableFace(TopoDS::Face(face.Current()))) return false;
  return true;
}

/// The solids of a component, or none when it is not only solids.
std::vector<TopoDS_Shape> solidsOf(const TopoDS_Shape& shape) {
  if (shape.IsNull()) return {};
  if (shape.ShapeType() == TopAbs_SOLID) return {shape};
  if (shape.ShapeType() != TopAbs_COMPOUND) return {};
  std::vector<TopoDS_Shape> solids;
  for (TopoDS_Iterator child(shape); child.More(); child.Next()) {
    std::vector<TopoDS_Shape> inner = solidsOf(child.Value());
    if (inner.empty()) return {};
    solids.insert(solids.end(), inner.begin(), inner.end());
  }
  return solids;
}

// ---- the text ----

/// A STEP real: the shortest text that reads back as the same double, with the decimal point
/// and upper-case exponent the exchange structure's syntax asks for (1. and 1.5E-07).
void appendReal(std::string& out, double value) {
  char buffer[32];
  const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
  (void)error;
  std::string_view text(buffer, static_cast<std::size_t>(end - buffer));
  const std::size_t exponent = text.find('e');
  const std::string_view mantissa = text.substr(0, exponent);
  out += mantissa;
  if (mantissa.find('.') == std::string_view::npos) out += '.';
  if (exponent != std::string_view::npos) {
    out += 'E';
    out += text.substr(exponent + 1);
  }
}

/// A STEP string: quotes doubled, characters beyond ASCII as \X2\ hexadecimal UTF-16 runs.
std::string stepString(const std::string& text) {
  std::string out = "'";
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    if (c == '\'') {
      out += "''";
    } else if (c == '\\') {
      out += "\\\\";
    } else if (c < 0x80) {
      out += static_cast<char>(c);
    } else {
      // Decode one UTF-8 sequence (basic multilingual plane) and write it as \X2\hhhh\X0\.
      unsigned code = 0;
      int extra = c >= 0xE0 ? 2 : 1;
      code = c & (extra == 2 ? 0x0F : 0x1F);
      for (int k = 0; k < extra && i + 1 < text.size(); ++k) code = (code << 6) | (text[++i] & 0x3F);
      char hex[16];
      std::snprintf(hex, sizeof hex, "\\X2\\%04X\\X0\\", code);
      out += hex;
    }
  }
  return out + "'";
}

/// The entities of the file, numbered in the order they are added.
class StepData {
 public:
  /// Starts an entity; the caller appends its text, then calls end().
  std::string& begin(int& id) {
    id = ++count_;
    std::string& out = current();
    out += '#';
    out += std::to_string(id);
    out += " = ";
    return out;
  }
  void end() { current() += ";\n"; }
  /// One whole entity.
  int add(const std::string& entity) {
    int id;
    begin(id) += entity;
    end();
    return id;
  }
  static std::string ref(int id) { return "#" + std::to_string(id); }
  /// The entities' text, in order.
  void writeTo(std::ostream& out) const {
    for (const std::string& chunk : chunks_) out << chunk;
  }

 private:
  /// The text is kept in chunks of about a megabyte: one string grown to the file's size
  /// would be copied to new memory at every doubling (a third of writing a 5 MB file went
  /// to copying and to the page faults of the fresh memory).
  std::string& current() {
    constexpr std::size_t kChunk = std::size_t(1) << 20;
    if (chunks_.empty() || chunks_.back().size() >= kChunk) {
      chunks_.emplace_back();
      chunks_.back().reserve(kChunk + kChunk / 4);
    }
    return chunks_.back();
  }

  std::vector<std::string> chunks_;
  int count_ = 0;
};

std::string refList(const std::vector<int>& ids) {
  std::string out = "(";
  for (std::size_t i = 0; i < ids.size(); ++i) out += (i ? "," : "") + StepData::ref(ids[i]);
  return out + ")";
}

std::string flag(bool value) { return value ? ".T." : ".F."; }

// ---- geometry ----

class GeometryWriter {
 public:
  explicit GeometryWriter(StepData& data) : data_(data) {}

  int point(const gp_Pnt& p) { return triple("CARTESIAN_POINT", p.X(), p.Y(), p.Z()); }
  int direction(const gp_Dir& d) { return triple("DIRECTION", d.X(), d.Y(), d.Z()); }

  int placement(const gp_Ax2& axes) {
    const int origin = point(axes.Location()), z = direction(axes.Direction()), x = direction(axes.XDirection());
    return data_.add("AXIS2_PLACEMENT_3D(''," + StepData::ref(origin) + "," + StepData::ref(z) + "," +
                     StepData::ref(x) + ")");
  }

  /// The surface's entity; `normalFlipped` tells when the entity's normal (STEP's: outward
  /// for elementary surfaces, whose axes are right-handed) is opposite to OCCT's.
  int surface(const Handle(Geom_Surface) & surface, bool& normalFlipped) {
    normalFlipped = false;
    if (auto plane = Handle(Geom_Plane)::DownCast(surface)) {
      // The axis along OCCT's normal (x × y, reversed to z in a left-handed placement).
      const gp_Ax3& position = plane->Position();
      const gp_Ax2 axes(position.Location(), position.XDirection().Crossed(position.YDirection()),
                        position.XDirection());
      return data_.add("PLANE(''," + StepData::ref(placement(axes)) + ")");
    }
    if (auto elementarySurface = Handle(Geom_ElementarySurface)::DownCast(surface)) {
      // STEP's placements are right-handed: the same axis and x direction, so the same point
      // set; a left-handed placement's y, and so the normal, comes out reversed.
      const gp_Ax3& position = elementarySurface->Position();
      gp_Ax2 axes(position.Location(), position.Direction(), position.XDirection());
      normalFlipped = !position.Direct();
      if (auto cylinder = Handle(Geom_CylindricalSurface)::DownCast(surface))
        return elementary("CYLINDRICAL_SURFACE", axes, {cylinder->Radius()});
      if (auto cone = Handle(Geom_ConicalSurface)::DownCast(surface)) {
        // STEP's semi-angle is positive: a cone opening the other way is the same surface, with
        // the same normals, about the reversed axis (its parameters both negated).
        if (cone->SemiAngle() < 0.0) axes = gp_Ax2(axes.Location(), axes.Direction().Reversed(), axes.XDirection());
        return elementary("CONICAL_SURFACE", axes, {cone->RefRadius(), std::abs(cone->SemiAngle())});
      }
      if (auto sphere = Handle(Geom_SphericalSurface)::DownCast(surface))
        return elementary("SPHERICAL_SURFACE", axes, {sphere->Radius()});
      if (auto torus = Handle(Geom_ToroidalSurface)::DownCast(surface))
        return elementary("TOROIDAL_SURFACE", axes, {torus->MajorRadius(), torus->MinorRadius()});
    }
    if (auto revolution = Handle(Geom_SurfaceOfRevolution)::DownCast(surface)) {
      // The swept curve as far as the surface is trimmed to it (its poles at the curve's ends).
      const Handle(Geom_Curve)& trimmed = revolution->BasisCurve();
      const int profile = curve(withoutTrimming(trimmed), trimmed->FirstParameter(), trimmed->LastParameter());
      const gp_Ax1 axis = revolution->Axis();
      const int axisPlacement = data_.add("AXIS1_PLACEMENT(''," + StepData::ref(point(axis.Location())) + "," +
                                          StepData::ref(direction(axis.Direction())) + ")");
      return data_.add("SURFACE_OF_REVOLUTION(''," + StepData::ref(profile) + "," + StepData::ref(axisPlacement) + ")");
    }
    return bsplineSurface(Handle(Geom_BSplineSurface)::DownCast(surface));
  }

  /// The curve of an edge over [first, last] of its parameters.
  int curve(const Handle(Geom_Curve) & curve, double first, double last) {
    if (auto line = Handle(Geom_Line)::DownCast(curve)) {
      const int origin = point(line->Position().Location());
      const int along = direction(line->Position().Direction());
      const int vector = data_.add("VECTOR(''," + StepData::ref(along) + ",1.)");
      return data_.add("LINE(''," + StepData::ref(origin) + "," + StepData::ref(vector) + ")");
    }
    if (auto circle = Handle(Geom_Circle)::DownCast(curve)) {
      std::string radius;
      appendReal(radius, circle->Radius());
      return data_.add("CIRCLE(''," + StepData::ref(placement(circle->Position())) + "," + radius + ")");
    }
    // The piece the edge uses, clamped: STEP knot vectors are explicit, and a periodic curve's
    // edge may run across its seam.
    Handle(Geom_BSplineCurve) piece = Handle(Geom_BSplineCurve)::DownCast(curve->Copy());
    if (piece->IsPeriodic()) piece->SetNotPeriodic();  // may keep knots of the neighbouring periods
    if (first > piece->FirstParameter() + 1e-12 || last < piece->LastParameter() - 1e-12 ||
        piece->FirstParameter() < first - 1e-12 || piece->LastParameter() > last + 1e-12)
      piece->Segment(first, last);
    return bsplineCurve(piece);
  }

 private:
  /// An elementary surface: its placement and its measures (lengths in metres, angles in radians).
  int elementary(const char* entity, const gp_Ax2& axes, std::initializer_list<double> measures) {
    std::string text = std::string(entity) + "(''," + StepData::ref(placement(axes));
    for (double measure : measures) {
      text += ',';
      appendReal(text, measure);
    }
    return data_.add(text + ")");
  }

  /// A point or a direction: its three coordinates.
  int triple(const char* entity, double x, double y, double z) {
    int id;
    std::string& out = data_.begin(id);
    out += entity;
    out += "('',(";
    appendReal(out, x);
    out += ',';
    appendReal(out, y);
    out += ',';
    appendReal(out, z);
    out += "))";
    data_.end();
    return id;
  }

  /// Consecutive CARTESIAN_POINTs; returns the first one's number.
  int points(const std::vector<gp_Pnt>& list) {
    int first = 0;
    for (std::size_t i = 0; i < list.size(); ++i) {
      const int id = point(list[i]);
      if (i == 0) first = id;
    }
    return first;
  }

  /// The list of references to `count` consecutive entities from `first`.
  static std::string consecutiveRefs(int first, int count) {
    std::string out = "(";
    for (int i = 0; i < count; ++i) {
      if (i > 0) out += ',';
      out += '#';
      out += std::to_string(first + i);
    }
    return out + ")";
  }

  static std::string integerList(const TColStd_Array1OfInteger& values) {
    std::string out = "(";
    for (int i = values.Lower(); i <= values.Upper(); ++i)
      out += (i > values.Lower() ? "," : "") + std::to_string(values(i));
    return out + ")";
  }

  static std::string realList(const TColStd_Array1OfReal& values) {
    std::string out = "(";
    for (int i = values.Lower(); i <= values.Upper(); ++i) {
      if (i > values.Lower()) out += ',';
      appendReal(out, values(i));
    }
    return out + ")";
  }

  int bsplineCurve(const Handle(Geom_BSplineCurve) & c) {
    std::vector<gp_Pnt> poleList;
    for (int i = 1; i <= c->NbPoles(); ++i) poleList.push_back(c->Pole(i));
    const std::string poles = consecutiveRefs(points(poleList), c->NbPoles());
    const std::string knots = integerList(c->Multiplicities()) + "," + realList(c->Knots());
    const std::string degree = std::to_string(c->Degree());
    if (!c->IsRational())
      return data_.add("B_SPLINE_CURVE_WITH_KNOTS(''," + degree + "," + poles + ",.UNSPECIFIED.,.F.,.F.," + knots +
                       ",.UNSPECIFIED.)");
    std::string weights = "(";
    for (int i = 1; i <= c->NbPoles(); ++i) {
      if (i > 1) weights += ',';
      appendReal(weights, c->Weight(i));
    }
    weights += ')';
    return data_.add("( BOUNDED_CURVE() B_SPLINE_CURVE(" + degree + "," + poles +
                     ",.UNSPECIFIED.,.F.,.F.) B_SPLINE_CURVE_WITH_KNOTS(" + knots +
                     ",.UNSPECIFIED.) CURVE() GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_CURVE(" + weights +
                     ") REPRESENTATION_ITEM('') )");
  }

  int bsplineSurface(Handle(Geom_BSplineSurface) s) {
    if (s->IsUPeriodic() || s->IsVPeriodic()) {
      // Clamped over the same period (SetNotPeriodic may keep knots of the neighbouring ones).
      s = Handle(Geom_BSplineSurface)::DownCast(s->Copy());
      double u0, u1, v0, v1;
      s->Bounds(u0, u1, v0, v1);
      if (s->IsUPeriodic()) s->SetUNotPeriodic();
      if (s->IsVPeriodic()) s->SetVNotPeriodic();
      s->Segment(u0, u1, v0, v1);
    }
    std::vector<gp_Pnt> poleList;
    for (int i = 1; i <= s->NbUPoles(); ++i)
      for (int j = 1; j <= s->NbVPoles(); ++j) poleList.push_back(s->Pole(i, j));
    const int first = points(poleList);
    std::string poles = "(";
    for (int i = 0; i < s->NbUPoles(); ++i)
      poles += (i > 0 ? "," : "") + consecutiveRefs(first + i * s->NbVPoles(), s->NbVPoles());
    poles += ')';
    // STEP lists u multiplicities, v multiplicities, u knots, v knots.
    const std::string knots = integerList(s->UMultiplicities()) + "," + integerList(s->VMultiplicities()) + "," +
                              realList(s->UKnots()) + "," + realList(s->VKnots());
    const std::string degrees = std::to_string(s->UDegree()) + "," + std::to_string(s->VDegree());
    if (!s->IsURational() && !s->IsVRational())
      return data_.add("B_SPLINE_SURFACE_WITH_KNOTS(''," + degrees + "," + poles + ",.UNSPECIFIED.,.F.,.F.,.F.," +
                       knots + ",.UNSPECIFIED.)");
    std::string weights = "(";
    for (int i = 1; i <= s->NbUPoles(); ++i) {
      weights += i > 1 ? ",(" : "(";
      for (int j = 1; j <= s->NbVPoles(); ++j) {
        if (j > 1) weights += ',';
        appendReal(weights, s->Weight(i, j));
      }
      weights += ')';
    }
    weights += ')';
    return data_.add("( BOUNDED_SURFACE() B_SPLINE_SURFACE(" + degrees + "," + poles +
                     ",.UNSPECIFIED.,.F.,.F.,.F.) B_SPLINE_SURFACE_WITH_KNOTS(" + knots +
                     ",.UNSPECIFIED.) GEOMETRIC_REPRESENTATION_ITEM() RATIONAL_B_SPLINE_SURFACE(" + weights +
                     ") REPRESENTATION_ITEM('') SURFACE() )");
  }

  StepData& data_;
};

// ---- topology ----

using FaceNames = NCollection_DataMap<TopoDS_Shape, std::string, TopTools_ShapeMapHasher>;

class TopologyWriter {
 public:
  TopologyWriter(StepData& data, GeometryWriter& geometry) : data_(data), geometry_(geometry) {}

  /// MANIFOLD_SOLID_BREP of one solid, named.
  int solid(const TopoDS_Shape& solid, const std::string& name, const FaceNames& faceNames) {
    std::vector<int> faces;
    for (TopExp_Explorer face(solid, TopAbs_FACE); face.More(); face.Next()) {
      const std::string* faceName = faceNames.Seek(face.Current());
      faces.push_back(this->face(TopoDS::Face(face.Current()), faceName ? *faceName : std::string()));
    }
    const int shell = data_.add("CLOSED_SHELL(''," + refList(faces) + ")");
    return data_.add("MANIFOLD_SOLID_BREP(" + stepString(name) + "," + StepData::ref(shell) + ")");
  }

 private:
  int vertex(const TopoDS_Vertex& v) {
    if (const int* known = vertices_.Seek(v)) return *known;
    const int id = data_.add("VERTEX_POINT(''," + StepData::ref(geometry_.point(BRep_Tool::Pnt(v))) + ")");
    vertices_.Bind(v, id);
    return id;
  }

  /// The EDGE_CURVE of an edge, from its first to its last vertex along its curve.
  int edge(const TopoDS_Edge& e) {
    if (const int* known = edges_.Seek(e)) return *known;
    const TopoDS_Edge forward = TopoDS::Edge(e.Oriented(TopAbs_FORWARD));
    TopoDS_Vertex from, to;
    TopExp::Vertices(forward, from, to);
    double first, last;
    const Handle(Geom_Curve) curve = basisCurve(forward, first, last);
    const int start = vertex(from), end = vertex(to), line = geometry_.curve(curve, first, last);
    const int id = data_.add("EDGE_CURVE(''," + StepData::ref(start) + "," + StepData::ref(end) + "," +
                             StepData::ref(line) + ",.T.)");
    edges_.Bind(e, id);
    return id;
  }

  int face(const TopoDS_Face& face, const std::string& name) {
    // Loops as they run on the face taken forward (material to their left about the
    // surface's normal); a reversed face says so and uses its bounds reversed.
    const bool sameSense = face.Orientation() != TopAbs_REVERSED;
    const TopoDS_Face forward = TopoDS::Face(face.Oriented(TopAbs_FORWARD));
    const TopoDS_Wire outer = BRepTools::OuterWire(forward);
    std::vector<int> bounds;
    for (TopoDS_Iterator item(forward); item.More(); item.Next()) {
      const TopoDS_Wire& wire = TopoDS::Wire(item.Value());
      std::vector<int> oriented;
      for (BRepTools_WireExplorer e(wire, forward); e.More(); e.Next()) {
        if (BRep_Tool::Degenerated(e.Current())) continue;  // a surface's pole: no edge in STEP
        oriented.push_back(data_.add("ORIENTED_EDGE('',*,*," + StepData::ref(edge(e.Current())) + "," +
                                     flag(e.Current().Orientation() != TopAbs_REVERSED) + ")"));
      }
      const int loop = data_.add("EDGE_LOOP(''," + refList(oriented) + ")");
      const char* kind = wire.IsSame(outer) ? "FACE_OUTER_BOUND" : "FACE_BOUND";
      bounds.push_back(data_.add(std::string(kind) + "(''," + StepData::ref(loop) + "," + flag(sameSense) + ")"));
    }
    bool normalFlipped = false;
    const int surface = geometry_.surface(basisSurface(forward), normalFlipped);
    return data_.add("ADVANCED_FACE(" + stepString(name) + "," + refList(bounds) + "," + StepData::ref(surface) + "," +
                     flag(sameSense != normalFlipped) + ")");
  }

  StepData& data_;
  GeometryWriter& geometry_;
  NCollection_DataMap<TopoDS_Shape, int, TopTools_ShapeMapHasher> vertices_, edges_;
};

// ---- products ----

/// The product of a part or of the assembly: its definition and shape definition.
struct Product {
  int definition;
  int representation;
};

class ProductWriter {
 public:
  ProductWriter(StepData& data, GeometryWriter& geometry) : data_(data), geometry_(geometry) {
    const int context = data_.add("APPLICATION_CONTEXT('core data for automotive mechanical design processes')");
    data_.add("APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000," +
              StepData::ref(context) + ")");
    applicationContext_ = context;
    const int metre = data_.add("( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT($,.METRE.) )");
    const int radian = data_.add("( NAMED_UNIT(*) PLANE_ANGLE_UNIT() SI_UNIT($,.RADIAN.) )");
    const int steradian = data_.add("( NAMED_UNIT(*) SI_UNIT($,.STERADIAN.) SOLID_ANGLE_UNIT() )");
    const int uncertainty = data_.add("UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07)," + StepData::ref(metre) +
                                      ",'distance_accuracy_value','confusion accuracy')");
    geometricContext_ = data_.add("( GEOMETRIC_REPRESENTATION_CONTEXT(3) GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT((" +
                                  StepData::ref(uncertainty) + ")) GLOBAL_UNIT_ASSIGNED_CONTEXT((" +
                                  StepData::ref(metre) + "," + StepData::ref(radian) + "," + StepData::ref(steradian) +
                                  ")) REPRESENTATION_CONTEXT('Context #1','3D Context with UNIT and UNCERTAINTY') )");
    origin_ = geometry_.placement(gp_Ax2());
  }

  int geometricContext() const { return geometricContext_; }
  int origin() const { return origin_; }

  /// A part or the assembly named `name` whose shape representation holds `items`.
  Product product(const std::string& name, const std::string& representationKind, const std::vector<int>& items) {
    const int productContext = data_.add("PRODUCT_CONTEXT(''," + StepData::ref(applicationContext_) + ",'mechanical')");
    const int product =
        data_.add("PRODUCT(" + stepString(name) + "," + stepString(name) + ",''," + refList({productContext}) + ")");
    data_.add("PRODUCT_RELATED_PRODUCT_CATEGORY('part',$," + refList({product}) + ")");
    const int formation = data_.add("PRODUCT_DEFINITION_FORMATION('',''," + StepData::ref(product) + ")");
    const int definitionContext =
        data_.add("PRODUCT_DEFINITION_CONTEXT('part definition'," + StepData::ref(applicationContext_) + ",'design')");
    const int definition = data_.add("PRODUCT_DEFINITION('design',''," + StepData::ref(formation) + "," +
                                     StepData::ref(definitionContext) + ")");
    const int shape = data_.add("PRODUCT_DEFINITION_SHAPE('',''," + StepData::ref(definition) + ")");
    const int representation =
        data_.add(representationKind + "(''," + refList(items) + "," + StepData::ref(geometricContext_) + ")");
    data_.add("SHAPE_DEFINITION_REPRESENTATION(" + StepData::ref(shape) + "," + StepData::ref(representation) + ")");
    return {definition, representation};
  }

  /// Places a part in the assembly where it is (the identity, at the assembly's placement `at`).
  void placeInAssembly(const Product& assembly, const Product& part, int at, int index, const std::string& name) {
    const int usage =
        data_.add("NEXT_ASSEMBLY_USAGE_OCCURRENCE(" + stepString(std::to_string(index)) + "," + stepString(name) +
                  ",''," + StepData::ref(assembly.definition) + "," + StepData::ref(part.definition) + ",$)");
    const int usageShape =
        data_.add("PRODUCT_DEFINITION_SHAPE('Placement','Placement of an item'," + StepData::ref(usage) + ")");
    const int transformation =
        data_.add("ITEM_DEFINED_TRANSFORMATION('',''," + StepData::ref(origin_) + "," + StepData::ref(at) + ")");
    const int relationship =
        data_.add("( REPRESENTATION_RELATIONSHIP('',''," + StepData::ref(part.representation) + "," +
                  StepData::ref(assembly.representation) + ") REPRESENTATION_RELATIONSHIP_WITH_TRANSFORMATION(" +
                  StepData::ref(transformation) + ") SHAPE_REPRESENTATION_RELATIONSHIP() )");
    data_.add("CONTEXT_DEPENDENT_SHAPE_REPRESENTATION(" + StepData::ref(relationship) + "," +
              StepData::ref(usageShape) + ")");
  }

 private:
  StepData& data_;
  GeometryWriter& geometry_;
  int applicationContext_ = 0, geometricContext_ = 0, origin_ = 0;
};

std::string header(const std::string& name) {
  char stamp[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(stamp, sizeof stamp, "%Y-%m-%dT%H:%M:%S", std::gmtime(&now));
  return "ISO-10303-21;\nHEADER;\nFILE_DESCRIPTION(('Airshape export'),'2;1');\nFILE_NAME(" + stepString(name) + ",'" +
         stamp + "',('Airshape'),(''),'Airshape STEP writer','Airshape','');\n" +
         "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n";
}

}  // namespace

bool brepStepWritable(const ExportScene& scene) {
  if (scene.components.empty()) return false;
  for (const SceneComponent& component : scene.components) {
    const std::vector<TopoDS_Shape> solids = solidsOf(component.shape.shape);
    if (solids.empty()) return false;
    for (const TopoDS_Shape& solid : solids)
      if (!writableSolid(solid)) return false;
  }
  return true;
}

void writeBrepStep(const ExportScene& scene, const std::string& path, const std::string& target) {
  StepData data;
  GeometryWriter geometry(data);
  ProductWriter products(data, geometry);
  TopologyWriter topology(data, geometry);

  std::vector<Product> parts;
  for (const SceneComponent& component : scene.components) {
    FaceNames faceNames;
    for (const auto& [name, face] : component.shape.faces)
      if (!faceNames.IsBound(face)) faceNames.Bind(face, name);
    std::vector<int> items{products.origin()};
    for (const TopoDS_Shape& solid : solidsOf(component.shape.shape))
      items.push_back(topology.solid(solid, component.name, faceNames));
    parts.push_back(products.product(component.name, "ADVANCED_BREP_SHAPE_REPRESENTATION", items));
  }
  // The assembly: one placement of its own and one per part, all the identity.
  std::vector<int> placements{products.origin()};
  for (std::size_t i = 0; i < parts.size(); ++i) placements.push_back(geometry.placement(gp_Ax2()));
  const Product assembly = products.product(scene.name, "SHAPE_REPRESENTATION", placements);
  for (std::size_t i = 0; i < parts.size(); ++i)
    products.placeInAssembly(assembly, parts[i], placements[i + 1], static_cast<int>(i) + 1, scene.components[i].name);

  std::ofstream file(path, std::ios::binary);
  file << header(scene.name);
  data.writeTo(file);
  file << "ENDSEC;\nEND-ISO-10303-21;\n";
  file.flush();
  if (!file) throw cannotWrite("STEP", target);
}

}  // namespace airshape::exporting
