#include "quality/mesh_quality.h"

#include <omp.h>

#include <Eigen/LU>
#include <algorithm>
#include <limits>
#include <optional>

#include "element/quad_reference_nodes.h"
#include "element/reference_nodes.h"
#include "quality/bezier_triangle.h"
#include "quality/ideal_jacobian.h"

namespace homesh {
namespace {

// The sample points of an order-p triangle or quadrilateral: the
// order-`lattice` reference lattice, plus the element nodes unless the lattice
// already holds them (lattice a multiple of p); node_point[i] is node i's point.
class LatticeSampling {
 public:
  LatticeSampling(int p, int lattice, ElementShape shape)
      : sampling_(p, points(p, lattice, shape, node_point_), shape) {
    if (shape == ElementShape::quadrilateral) return;  // J from the Lagrange basis
    const Eigen::Matrix2Xd& uv = sampling_.points();
    bernstein_.resize(bezier_size(p - 1), uv.cols());
    for (Eigen::Index k = 0; k < uv.cols(); ++k)
      bernstein_.col(k) = p * bernstein_basis(p - 1, uv.col(k));
  }

  int size() const { return sampling_.size(); }

  // Per-thread storage for one element's samples.
  struct Work {
    explicit Work(int points) : W(points), det(points), value(points) {}
    std::vector<Eigen::Matrix2d> W;
    std::vector<double> det, value;
  };

  // Measures qs of triangle e (nodes X, derivative control points U, V) into
  // column e of each result.
  void measure(const std::vector<const Measure*>& qs, Reference ref, const Eigen::Matrix2Xd& X,
               const JacobianControlPoints& U, const JacobianControlPoints& V, int e, Work& w,
               std::vector<MeshMeasure>& out) const {
    const Eigen::Matrix2d to_ideal = reference_to_ideal_jacobian().inverse();
    const int points = size(), q = static_cast<int>(U.cols());
    for (int k = 0; k < points; ++k) {
      // J = p sum_c B^{p-1}_c [U.col(c) V.col(c)] (p folded into bernstein_).
      const double* b = bernstein_.col(k).data();
      Eigen::Matrix2d J = Eigen::Matrix2d::Zero();
      for (int c = 0; c < q; ++c) {
        J.col(0) += b[c] * U.col(c);
        J.col(1) += b[c] * V.col(c);
      }
      w.W[k].noalias() = J * to_ideal;  // W = J inv(J_ri), as ideal_jacobian
      w.det[k] = w.W[k].determinant();
    }
    evaluate(qs, ref, X, e, w, out);
  }

  // Measures qs of quadrilateral e (nodes X) into column e of each result. The
  // ideal element is the unit square, the reference square itself: W = J.
  void measure(const std::vector<const Measure*>& qs, Reference ref, const Eigen::Matrix2Xd& X,
               int e, Work& w, std::vector<MeshMeasure>& out) const {
    for (int k = 0; k < size(); ++k) {
      w.W[k] = sampling_.jacobian(X, k);
      w.det[k] = w.W[k].determinant();
    }
    evaluate(qs, ref, X, e, w, out);
  }

 private:
  // The measures from W and det W at every point (in w) into column e.
  void evaluate(const std::vector<const Measure*>& qs, Reference ref, const Eigen::Matrix2Xd& X,
                int e, Work& w, std::vector<MeshMeasure>& out) const {
    const int points = size();
    std::vector<double>& value = w.value;
    for (std::size_t j = 0; j < qs.size(); ++j) {
      const Measure& m = *qs[j];
      if (!m.pointwise()) {
        std::fill(value.begin(), value.end(), m.element(sampling_, X));
      } else if (ref == Reference::element_max && m.thesis_max_normalised) {
        // point_quality's raw / max raw (element_quality.h), each raw value
        // computed once.
        double max_raw = 0.0;
        for (int k = 0; k < points; ++k) {
          value[k] = m.raw(w.W[k]);
          if (w.det[k] > 0.0) max_raw = std::max(max_raw, value[k]);
        }
        for (int k = 0; k < points; ++k)
          value[k] = w.det[k] <= 0.0 || !(max_raw > 0.0) ? 0.0 : value[k] / max_raw;
      } else {
        for (int k = 0; k < points; ++k) value[k] = m.quality(w.W[k]);
      }
      double lowest = 1.0;
      for (const double v : value) lowest = std::min(lowest, v);
      for (std::size_t i = 0; i < node_point_.size(); ++i)
        out[j].node_values(static_cast<Eigen::Index>(i), e) = value[node_point_[i]];
      out[j].element_min(e) = lowest;
    }
  }

  static Eigen::Matrix2Xd points(int p, int lattice, ElementShape shape,
                                 std::vector<int>& node_point) {
    const bool quad = shape == ElementShape::quadrilateral;
    const auto indices = quad ? quad_reference_node_indices : reference_node_indices;
    const Eigen::Matrix2Xi node_index = indices(p);
    const auto nodes = static_cast<int>(node_index.cols());
    Eigen::Matrix2Xd uv = indices(lattice).cast<double>() * (1.0 / lattice);
    node_point.resize(static_cast<std::size_t>(nodes));
    if (lattice % p == 0) {
      const Eigen::Matrix2Xi on_lattice = indices(lattice);
      for (int i = 0; i < nodes; ++i)
        for (int k = 0; k < on_lattice.cols(); ++k)
          if (on_lattice.col(k) == node_index.col(i) * (lattice / p)) node_point[i] = k;
    } else {
      const Eigen::Index l = uv.cols();
      uv.conservativeResize(2, l + nodes);
      uv.rightCols(nodes) = node_index.cast<double>() * (1.0 / p);
      for (int i = 0; i < nodes; ++i) node_point[i] = static_cast<int>(l) + i;
    }
    return uv;
  }

  std::vector<int> node_point_;  // filled by points(), before sampling_
  ElementSampling sampling_;     // the points, for measures of the whole element
  Eigen::MatrixXd bernstein_;    // bezier_size(p-1) by points: p B^{p-1}_c(point)
};

// How many triangles ahead the loop requests nodes from memory.
constexpr int kPrefetchAhead = 4;

// The one loop over the triangles and quadrilaterals: bounds if `bounds`,
// measures if qs is not empty. With `known` (bounds only), the elements none of
// whose nodes moved (moved[i] false) take their bounds from it.
MeshQuality sweep(const Mesh& m, const std::vector<const Measure*>& qs, int lattice, Reference ref,
                  const BoundsOptions* bounds, int threads, const MeshValidity* known = nullptr,
                  const std::vector<char>* moved = nullptr) {
  const int p = m.order, triangles = m.num_triangles(), n = m.num_elements_2d();
  const int q = bezier_size(p - 1);
  std::optional<LatticeSampling> sampling, quad_sampling;
  if (!qs.empty() && triangles > 0) sampling.emplace(p, lattice, ElementShape::triangle);
  if (!qs.empty() && m.num_quads() > 0)
    quad_sampling.emplace(p, lattice, ElementShape::quadrilateral);
  MeshQuality r;
  MeshValidity& v = r.validity;
  std::vector<char> converged;
  if (bounds) {
    v.ratio.resize(n);
    v.min_det.resize(n);
    v.relative_tolerance = bounds->relative_tolerance;
    v.max_subdivisions = bounds->max_subdivisions;
    converged.resize(static_cast<std::size_t>(n));
  }
  r.measures.resize(qs.size());
  for (auto& out : r.measures) {
    out.element_min.resize(n);
    // With quadrilaterals, a triangle's column has rows below its nodes: NaN.
    out.node_values.setConstant(m.num_quads() > 0 ? quad_node_count(p) : triangle_node_count(p), n,
                                std::numeric_limits<double>::quiet_NaN());
  }
#pragma omp parallel num_threads(threads > 0 ? threads : omp_get_max_threads())
  {
    Eigen::Matrix2Xd X(2, triangle_node_count(p)), Xq(2, quad_node_count(p));
    JacobianControlPoints U(2, q), V(2, q);
    LatticeSampling::Work work(sampling ? sampling->size() : 0);
    LatticeSampling::Work quad_work(quad_sampling ? quad_sampling->size() : 0);
#pragma omp for schedule(dynamic, 256)
    for (int e = 0; e < n; ++e) {
      if (known) {
        bool still = true;
        for (const int i : element_node_indices(m, e)) still = still && !(*moved)[i];
        if (still) {
          v.ratio(e) = known->ratio(e);
          v.min_det(e) = known->min_det(e);
          converged[e] = known->converged[e];
          continue;
        }
      }
      if (e >= triangles) {
        const int k = e - triangles;
        for (int i = 0; i < Xq.cols(); ++i) Xq.col(i) = m.x.col(m.quad(i, k));
        if (bounds) {
          const JacobianBounds b = quad_jacobian_bounds(Xq, p, *bounds);
          v.ratio(e) = scaled_jacobian_ratio(b);
          v.min_det(e) = b.min_lower;
          converged[e] = b.converged;
        }
        if (quad_sampling) quad_sampling->measure(qs, ref, Xq, e, quad_work, r.measures);
        continue;
      }
      // The nodes of a triangle a few ahead are requested now: on large
      // meshes waiting for them would otherwise take much of the time.
      if (e + kPrefetchAhead < triangles)
        for (int i = 0; i < X.cols(); ++i)
          __builtin_prefetch(m.x.col(m.tri(i, e + kPrefetchAhead)).data());
      for (int i = 0; i < X.cols(); ++i) X.col(i) = m.x.col(m.tri(i, e));
      jacobian_control_points(X, p, U, V);
      if (bounds) {
        const JacobianBounds b = jacobian_bounds(U, V, p, *bounds);
        v.ratio(e) = scaled_jacobian_ratio(b);
        v.min_det(e) = b.min_lower;
        converged[e] = b.converged;
      }
      if (sampling) sampling->measure(qs, ref, X, U, V, e, work, r.measures);
    }
  }
  if (bounds) {
    v.converged = std::move(converged);
    count_validity(v);
  }
  return r;
}

}  // namespace

std::vector<MeshMeasure> mesh_measures(const Mesh& m, const std::vector<const Measure*>& qs,
                                       int lattice, Reference ref) {
  return sweep(m, qs, lattice, ref, nullptr, 0).measures;
}

MeshQuality mesh_quality(const Mesh& m, const std::vector<const Measure*>& qs, int lattice,
                         Reference ref, const BoundsOptions& opt, int threads) {
  return sweep(m, qs, lattice, ref, &opt, threads);
}

MeshValidity moved_elements_validity(const Mesh& m, const std::vector<char>& moved,
                                     const MeshValidity& known, const BoundsOptions& opt) {
  return sweep(m, {}, 0, Reference::ideal, &opt, 0, &known, &moved).validity;
}

}  // namespace homesh
