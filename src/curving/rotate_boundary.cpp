#include "curving/rotate_boundary.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

#include "core/error.h"
#include "core/progress.h"
#include "fem/solve_elasticity.h"
#include "quality/mesh_validity.h"

namespace homesh {
namespace {

Eigen::Matrix2d rotation(double degrees) {
  const double a = degrees * M_PI / 180.0;
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

void check(const Mesh& m, const std::vector<bool>& wall, const std::vector<bool>& prescribed,
           const RotateOptions& opt) {
  const auto n = static_cast<std::size_t>(m.num_nodes());
  if (wall.size() != n || prescribed.size() != n)
    throw Error("rotate_boundary: wall and prescribed must have one entry per node");
  bool any = false;
  for (std::size_t i = 0; i < n; ++i) {
    if (wall[i] && !prescribed[i])
      throw Error("rotate_boundary: wall node " + std::to_string(i) + " is not prescribed");
    any = any || wall[i];
  }
  if (!any) throw Error("rotate_boundary: the wall has no nodes");
  if (!(opt.step != 0 && std::isfinite(opt.step)))
    throw Error("rotate_boundary: the angle step must be finite and nonzero");
  if (!(opt.max_angle >= 0 && std::isfinite(opt.max_angle)))
    throw Error("rotate_boundary: max_angle must be finite and >= 0");
  // A cap instead of a run of a billion steps (step=1e-9).
  const double steps = opt.max_angle / std::abs(opt.step);
  if (steps > kMaxRotationSteps) {
    std::ostringstream s;
    s << "rotate_boundary: turning to " << opt.max_angle << " degrees by " << std::abs(opt.step)
      << " would take " << steps << " steps; at most " << kMaxRotationSteps
      << " are allowed: use a larger step or a smaller max";
    throw Error(s.str());
  }
  if (opt.substeps < 1) throw Error("rotate_boundary: substeps must be >= 1");
}

// The centre of the circle fitted to the wall's nodes.
Eigen::Vector2d wall_centre(const Mesh& m, const std::vector<bool>& wall) {
  Eigen::Matrix2Xd points(2, std::count(wall.begin(), wall.end(), true));
  for (int i = 0, k = 0; i < m.num_nodes(); ++i)
    if (wall[i]) points.col(k++) = m.x.col(i);
  return fitted_circle_centre(points);
}

}  // namespace

RotateResult rotate_boundary(const Mesh& m, const std::vector<bool>& wall,
                             const std::vector<bool>& prescribed, const RotateOptions& opt) {
  check(m, wall, prescribed, opt);
  const AnalogyFormulation& formulation = analogy_formulation(opt.formulation);
  ElasticityOptions eo;
  eo.assembly = opt.params.assembly;
  eo.solver = opt.solver;

  const MeshValidity start = mesh_validity(m);
  if (start.invalid > 0)
    throw Error("rotate_boundary: " + std::to_string(start.invalid) +
                " triangles of the initial mesh are not certified valid");
  RotateResult r;
  r.mesh = m;
  r.worst_ratio = start.worst;
  r.centre = opt.centre ? *opt.centre : wall_centre(m, wall);
  Mesh current = m;
  Eigen::Matrix2Xd guess;
  long iterations = 0;
  const int max_steps = static_cast<int>(std::floor(opt.max_angle / std::abs(opt.step) + 1e-9));
  const int solves_per_step = opt.total ? 1 : opt.substeps;
  bool failed = false;
  Progress progress("step", max_steps);
  while (r.steps < max_steps && !failed) {
    double step_worst = 1.0;
    for (int s = 1; s <= solves_per_step && !failed; ++s) {
      const double angle = opt.step * (r.steps + double(s) / solves_per_step);
      const Eigen::Matrix2d R = rotation(angle);
      const Mesh& base = opt.total ? m : current;
      DirichletBC bc;
      for (int i = 0; i < m.num_nodes(); ++i) {
        if (!prescribed[i]) continue;
        const Eigen::Vector2d x0 = m.x.col(i);
        const Eigen::Vector2d to = wall[i] ? Eigen::Vector2d(R * (x0 - r.centre) + r.centre) : x0;
        bc.fix(i, Eigen::Vector2d(to - base.x.col(i)));
      }
      const ElasticitySolution u =
          solve_elasticity(base, formulation.coefficients(base, m, opt.params), bc, eo, guess);
      ++r.solves;
      iterations += u.iterations;
      Mesh trial = base;
      trial.x += u.u;
      const MeshValidity v = mesh_validity(trial);
      if (v.invalid > 0) {
        r.invalid_at_failure = v.invalid;
        failed = true;
        continue;
      }
      step_worst = std::min(step_worst, v.worst);
      guess = u.u;
      current = std::move(trial);
    }
    if (failed) break;
    ++r.steps;
    r.mesh = current;
    r.worst_ratio = std::min(r.worst_ratio, step_worst);
    char angle[32];
    std::snprintf(angle, sizeof angle, "%g deg", r.steps * opt.step);
    progress.update(r.steps, angle);
  }
  r.theta_max = r.steps * std::abs(opt.step);
  r.reached_max = !failed;
  const int attempted = r.steps + (failed ? 1 : 0);
  r.mean_iterations = attempted > 0 ? double(iterations) / attempted : 0.0;
  for (int i = 0; i < r.mesh.num_nodes(); ++i)
    if (wall[i] && r.steps > 0) r.mesh.node_class[i].u = std::numeric_limits<double>::quiet_NaN();
  return r;
}

Eigen::Vector2d fitted_circle_centre(const Eigen::Matrix2Xd& points) {
  if (points.cols() < 3) throw Error("fitted_circle_centre: needs at least 3 points");
  // |x|^2 = 2 c . x + k, k = r^2 - |c|^2: least squares in (c, k).
  Eigen::MatrixXd A(points.cols(), 3);
  A.leftCols(2) = 2 * points.transpose();
  A.col(2).setOnes();
  const Eigen::VectorXd b = points.colwise().squaredNorm().transpose();
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(A);
  if (qr.rank() < 3) throw Error("fitted_circle_centre: the points are collinear");
  const Eigen::Vector3d c = qr.solve(b);
  return c.head<2>();
}

}  // namespace homesh
