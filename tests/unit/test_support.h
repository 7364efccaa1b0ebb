#pragma once

#include <string>
#include <vector>

#include "airshape/graph/component_graph.h"

namespace airshape::test {

/// A minimal CPACS 3.5 document whose aircraft model holds `modelBody` (fuselages, wings...).
inline std::string cpacsDocument(const std::string& modelBody, const std::string& vehiclesExtra = "") {
  return R"(<?xml version="1.0" encoding="UTF-8"?>
<cpacs>
  <header>
    <name>test</name>
    <version>1</version>
    <versionInfos><versionInfo version="1"><creator>test</creator><timestamp>2026-01-01T00:00:00</timestamp>
      <description>test</description><cpacsVersion>3.5</cpacsVersion></versionInfo></versionInfos>
  </header>
  <vehicles>
    <aircraft>
      <model uID="M">
        <name>model</name>
)" + modelBody +
         R"(
      </model>
    </aircraft>)" +
         vehiclesExtra + R"(
  </vehicles>
</cpacs>
)";
}

/// Where the core's tests find components: wings and fuselages with their segments, declared as
/// the wing and fuselage plugins declare them (the core itself knows no kind).
inline std::vector<graph::ComponentLocation> bodyLocations() {
  using graph::ComponentLocation;
  return graph::resolveLocations(
      {ComponentLocation{"fuselage", "fuselages/fuselage"}.inBox().placedByItsTransformation(),
       ComponentLocation{"fuselageSegment", "segments/segment"}.inside("fuselage").typed("fuselage_segment").asPart(),
       ComponentLocation{"wing", "wings/wing"}.inBox().placedByItsTransformation(),
       ComponentLocation{"wingSegment", "segments/segment"}.inside("wing").typed("wing_segment").asPart()});
}

/// A wing with two sections and one segment; `extra` goes inside <wing>.
inline std::string wingXml(const std::string& uid, const std::string& parent = "", const std::string& attributes = "") {
  const std::string parentElement = parent.empty() ? "" : "<parentUID>" + parent + "</parentUID>";
  return "<wing uID=\"" + uid + "\"" + attributes + "><name>" + uid + "</name>" + parentElement +
         "<transformation><scaling><x>1</x><y>1</y><z>1</z></scaling></transformation>"
         "<sections><section uID=\"" +
         uid + "_S1\"><name>s1</name><transformation/><elements><element uID=\"" + uid +
         "_S1E\"><name>e</name><airfoilUID>A</airfoilUID><transformation/></element></elements></section>"
         "<section uID=\"" +
         uid + "_S2\"><name>s2</name><transformation/><elements><element uID=\"" + uid +
         "_S2E\"><name>e</name><airfoilUID>A</airfoilUID><transformation/></element></elements></section></sections>"
         "<segments><segment uID=\"" +
         uid + "_Seg\"><name>seg</name><fromElementUID>" + uid + "_S1E</fromElementUID><toElementUID>" + uid +
         "_S2E</toElementUID></segment></segments></wing>";
}

}  // namespace airshape::test
