#pragma once
// Galerkin assembly of the elastic analogy on the high-order elements of a mesh,
// thesis Eqs 4.10-4.15: the global system K x = p + b of Eq 4.13 before the
// Dirichlet conditions (fem/dirichlet.h) are applied.
#include <Eigen/Core>
#include <Eigen/SparseCore>

#include "core/mesh.h"
#include "fem/elasticity_coefficients.h"

namespace homesh {

struct AssemblyOptions {
  /// Added to 2 (p - 1), the degree exact for straight triangles with constant
  /// coefficients (stiffness_quadrature_degree), and to 2 p per variable, that
  /// of parallelograms (quad_stiffness_quadrature_degree), for curved elements
  /// and varying coefficients; the body force and thermal terms use the same rules.
  int quadrature_margin = 2;
  /// Static condensation in the repeated assembly (fem/elasticity_assembler.h): the
  /// dofs of nodes in one element only, both components free (the interior nodes of
  /// triangles from p = 3 and of quadrilaterals from p = 2), are eliminated element by
  /// element before the global system is formed and recovered from its solution
  /// (Guyan, AIAA J. 3, 1965; the standard treatment of high-order elements' bubble
  /// modes, e.g. Karniadakis & Sherwin, "Spectral/hp element methods", 2005, Sec 4.2).
  /// The same displacements to rounding with a global system of fewer dofs: at p = 5,
  /// 6 of a triangle's 21 nodes are interior, nearly half of the mesh's dofs. The curve
  /// stage on issue 16's corpus at p = 5 (fresh processes, medians of 6, without / with):
  /// circles6_nolayer 102 / 88 ms, circle_voronoi 42 / 33 ms, star4_nolayer_coarse
  /// 37 / 29 ms; the meshes the same.
  /// assemble_elasticity (the whole system) never condenses.
  bool condense = true;
  /// Threads of the repeated assembly's element loops (0: one per core, whatever
  /// OpenMP's default is: a Gmsh-API script's gmsh.initialize sets that to 1), used only
  /// where the elements' work is worth a team (ElasticityAssembler). The system is the
  /// same for any count (the elements of one colour share no entry).
  int threads = 0;
};

/// A sparse symmetric system K x = b over the 2 #nodes displacement dofs,
/// interleaved: dof 2 i + c is component c (0: x, 1: y) of node i.
struct LinearSystem {
  Eigen::SparseMatrix<double> K;
  Eigen::VectorXd b;
};

/// K (full storage, both triangles) and b summed from element_stiffness and
/// element_load over the triangles and quadrilaterals of m (order m.order,
/// nodes m.x, m.tri, m.quad), with the coefficients c evaluated at every
/// quadrature point of every element (QuadraturePoint{e, q, x_q}, e the 2D
/// element index: triangle e for e < T = #triangles, else quadrilateral
/// e - T; q indexes the triangle's or the quadrilateral's rule).
/// Natural boundaries are traction free. Nodes in no element get the
/// equation u = 0 (unit diagonal, zero load).
/// Throws homesh::Error naming the element if an element is invalid (det J
/// vanishes or changes sign) or a coefficient is out of range.
LinearSystem assemble_elasticity(const Mesh& m, const ElasticityCoefficients& c,
                                 const AssemblyOptions& options = {});

}  // namespace homesh
