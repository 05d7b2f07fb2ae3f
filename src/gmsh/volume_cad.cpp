#include "gmsh/volume_cad.h"

#include <gmsh.h>

#include "core/error.h"
#include "gmsh/gmsh_call.h"

namespace homesh::gmsh_adapter {

VolumeCad volume_cad() {
  VolumeCad cad;
  cad.has_geometry = [](int dim, int tag) {
    std::string type;
    gmsh_call("the CAD of the current model", [&] { gmsh::model::getType(dim, tag, type); });
    return type.rfind("Discrete", 0) != 0;
  };
  cad.closest = [](int dim, int tag, const Eigen::Matrix3Xd& x) {
    std::vector<double> coord(x.data(), x.data() + x.size()), closest, param;
    gmsh_call(
        "projecting nodes on entity (" + std::to_string(dim) + ", " + std::to_string(tag) + ")",
        [&] { gmsh::model::getClosestPoint(dim, tag, coord, closest, param); });
    Eigen::Matrix3Xd y(3, x.cols());
    if (closest.size() != coord.size()) {
      y.setConstant(std::numeric_limits<double>::quiet_NaN());
      return y;
    }
    y = Eigen::Map<const Eigen::Matrix3Xd>(closest.data(), 3, x.cols());
    return y;
  };
  cad.value = [](int dim, int tag, const Eigen::MatrixXd& params) {
    std::vector<double> at(params.data(), params.data() + params.size()), xyz;
    gmsh_call("evaluating entity (" + std::to_string(dim) + ", " + std::to_string(tag) + ")",
              [&] { gmsh::model::getValue(dim, tag, at, xyz); });
    Eigen::Matrix3Xd y =
        Eigen::Matrix3Xd::Constant(3, params.cols(), std::numeric_limits<double>::quiet_NaN());
    if (xyz.size() == static_cast<std::size_t>(3 * params.cols()))
      y = Eigen::Map<const Eigen::Matrix3Xd>(xyz.data(), 3, params.cols());
    return y;
  };
  cad.bounds = [](int dim, int tag) {
    std::vector<double> lo, hi;
    gmsh_call(
        "parameter range of entity (" + std::to_string(dim) + ", " + std::to_string(tag) + ")",
        [&] { gmsh::model::getParametrizationBounds(dim, tag, lo, hi); });
    Eigen::MatrixXd b = Eigen::MatrixXd::Constant(dim, 2, std::numeric_limits<double>::quiet_NaN());
    for (int d = 0; d < dim && d < static_cast<int>(std::min(lo.size(), hi.size())); ++d)
      b.row(d) << lo[d], hi[d];
    return b;
  };
  cad.derivatives = [](int dim, int tag, const Eigen::MatrixXd& params) {
    std::vector<double> at(params.data(), params.data() + params.size()), d;
    gmsh_call("derivatives of entity (" + std::to_string(dim) + ", " + std::to_string(tag) + ")",
              [&] { gmsh::model::getDerivative(dim, tag, at, d); });
    Eigen::MatrixXd out =
        Eigen::MatrixXd::Constant(3 * dim, params.cols(), std::numeric_limits<double>::quiet_NaN());
    if (d.size() == static_cast<std::size_t>(3 * dim * params.cols()))
      out = Eigen::Map<const Eigen::MatrixXd>(d.data(), 3 * dim, params.cols());
    return out;
  };
  // Gmsh 4.8.4's getClosestPoint returns zeros for the parameters: they come
  // from getParametrization, which refuses a whole batch if one point fails.
  cad.parameters = [](int dim, int tag, const Eigen::Matrix3Xd& x) {
    Eigen::MatrixXd params =
        Eigen::MatrixXd::Constant(dim, x.cols(), std::numeric_limits<double>::quiet_NaN());
    const auto find = [&](Eigen::Index first, Eigen::Index count) {
      std::vector<double> coord(x.data() + 3 * first, x.data() + 3 * (first + count)), p;
      try {
        gmsh_call("parameters", [&] { gmsh::model::getParametrization(dim, tag, coord, p); });
      } catch (const Error&) {
        return false;
      }
      if (p.size() != static_cast<std::size_t>(dim * count)) return false;
      params.middleCols(first, count) = Eigen::Map<const Eigen::MatrixXd>(p.data(), dim, count);
      return true;
    };
    if (!find(0, x.cols()))
      for (Eigen::Index k = 0; k < x.cols(); ++k) find(k, 1);
    return params;
  };
  cad.directions = [parameters = cad.parameters](int dim, int tag, const Eigen::Matrix3Xd& x) {
    Eigen::Matrix3Xd out =
        Eigen::Matrix3Xd::Constant(3, x.cols(), std::numeric_limits<double>::quiet_NaN());
    const Eigen::MatrixXd uv = parameters(dim, tag, x);
    for (Eigen::Index k = 0; k < x.cols(); ++k) {
      if (!uv.col(k).allFinite()) continue;
      std::vector<double> at(uv.col(k).data(), uv.col(k).data() + dim), v;
      try {
        gmsh_call("directions", [&] {
          if (dim == 2)
            gmsh::model::getNormal(tag, at, v);
          else
            gmsh::model::getDerivative(1, tag, at, v);
        });
      } catch (const Error&) {
        continue;
      }
      if (v.size() < 3) continue;
      const Eigen::Vector3d d(v[0], v[1], v[2]);
      if (d.norm() > 0) out.col(k) = d.normalized();
    }
    return out;
  };
  return cad;
}

}  // namespace homesh::gmsh_adapter
