#pragma once
// The formulations of the augmented elastic analogy compared in thesis
// Section 4.4 (Tables 4.1-4.9, Section 4.4.2), registered by name. Each turns
// the current mesh into the coefficients of the elasticity problem
// (fem/elasticity_coefficients.h); they are re-evaluated at every load step.
//
// Sign convention: `heat` > 0 makes hot elements expand (a "heated" distorted
// element resists being squashed further, Section 4.4.1). In Eq 4.5 the thermal
// stress adds to the stress, so the coefficient passed on is beta = -heat.
// Stress-free temperature T0 = 1: an undistorted element (min Q / max Q = 1) is
// not heated.
//
// Meshes of triangles and quadrilaterals alike: per-element quantities are
// indexed by 2D element (triangles, then quadrilaterals, core/mesh.h) and
// per-point ones follow each kind's rule (fem/elasticity_assembler.h). The
// ideal element of a quadrilateral is the unit square, so its ideal->physical
// Jacobian W is J (metric_ideal, Q11 of stiff_shape), as for the quality
// measures (quality/mesh_quality.h); its Q17 ratio and Q11 are taken over the
// order-2p lattice of the square.
#include <string>
#include <vector>

#include "core/mesh.h"
#include "fem/assemble_elasticity.h"
#include "fem/elasticity_coefficients.h"

namespace homesh {

struct FormulationParams {
  double poisson = 0.4;  ///< nu
  double heat = 1.0;     ///< scale of the added terms (body force, heat), see above
  /// Exponent of the stiffening E = (min Q17 / max Q17)^-power of stiff_q17
  /// (and of stiff_shape's E = (q / q0)^-power and stiff_shear's
  /// mu = (R_e q_F)^-power, for which 3 is the benchmarked value)
  /// (thesis case 8: power 1; higher powers stiffen distorted elements harder,
  /// a homesh extension measured by scripts/rotation_benchmark.py).
  double power = 1.0;
  AssemblyOptions assembly;  ///< must match the assembly that uses the coefficients
};

struct AnalogyFormulation {
  std::string name;
  std::string description;  ///< E, f, T / sigma_t as in Table 4.9
  /// Coefficients on the current mesh m; `initial` is the mesh the deformation
  /// started from (same connectivity).
  ElasticityCoefficients (*coefficients)(const Mesh& m, const Mesh& initial,
                                         const FormulationParams& p);
};

/// All formulations: plain, area, force_q17, heat_q17, heat_q4, metric_ref,
/// metric_ideal, stiff_q17 (Table 4.9 cases 1-8), heat_area (T = 1/Ae,
/// Section 4.4.2), stiff_shape (homesh: E from the loss of Q11 shape
/// quality since the start) and stiff_shear (homesh: the shear modulus from
/// case 8's ratio and the shear of the deformation since the start, per
/// quadrature point; the best on the rotation benchmark).
const std::vector<AnalogyFormulation>& analogy_formulations();

/// The names of all formulations joined by " | ", for option help texts.
std::string analogy_formulation_names();

/// The formulation called `name`; homesh::Error listing the names if none.
const AnalogyFormulation& analogy_formulation(const std::string& name);

}  // namespace homesh
