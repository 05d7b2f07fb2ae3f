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
  return cad;
}

}  // namespace homesh::gmsh_adapter
