#include "mesh_writers.h"

#include "abaqus_writer.h"
#include "airshape/output_file.h"
#include "msh_writer.h"
#include "stl_writer.h"
#include "su2_writer.h"
#include "vtu_writer.h"

namespace airshape::meshing {

void writeMesh(const MeshTables& tables, const std::string& path, MeshFormat format) {
  writeFileSafely(path, [&](const std::string& temporary) {
    switch (format) {
      case MeshFormat::Msh:
        return writeMsh(tables, temporary);
      case MeshFormat::Su2:
        return writeSu2(tables, temporary);
      case MeshFormat::Vtu:
        return writeVtu(tables, temporary);
      case MeshFormat::Inp:
        return writeAbaqus(tables, temporary);
      case MeshFormat::Stl:
        return writeStl(tables, temporary);
    }
  });
}

}  // namespace airshape::meshing
