// A tunnel and gmsh's own writings of a .msh, shared by the .msh tests
// (msh_io_test.cpp, msh_child_test.cpp).
#pragma once

#include <gmsh.h>

#include <string>

#include "rockfdem/mesh/mesh_spec.hpp"

namespace rockfdem::mesh::test {

/// A circular tunnel (radius 3 m) with a 0.3 m lining and a 1 m fracture
/// zone in a 24 m box, meshed coarsely (0.6 m near, 3 m far).
inline MeshSpec lined_circular_tunnel() {
  MeshSpec s;
  s.tunnel.shape = TunnelShape::kCircular;
  s.tunnel.radius = 3, s.tunnel.lining_thickness = 0.3;
  s.tunnel.fracture_zone = 1;
  s.domain = {24, 24, 0, 0};
  s.size.size_near = 0.6, s.size.size_far = 3;
  return s;
}

/// The .msh `from` written again by gmsh to `to` as MSH `version`, with
/// Mesh.SaveAll = 0 (as gmsh 2.x wrote every file: an element once per
/// physical group it is in), binary when asked.
inline void gmsh_rewrite(const std::string& from, const std::string& to, double version,
                         bool binary = false) {
  gmsh::initialize();
  gmsh::option::setNumber("General.Terminal", 0);
  gmsh::open(from);
  gmsh::option::setNumber("Mesh.MshFileVersion", version);
  gmsh::option::setNumber("Mesh.SaveAll", 0);
  gmsh::option::setNumber("Mesh.Binary", binary ? 1 : 0);
  gmsh::write(to);
  gmsh::finalize();
}

}  // namespace rockfdem::mesh::test
