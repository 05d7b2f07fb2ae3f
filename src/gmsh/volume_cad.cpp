#include "gmsh/volume_cad.h"

#include <gmsh.h>

#include "gmsh/gmsh_call.h"

namespace homesh::gmsh_adapter {

VolumeCad volume_cad() {
  VolumeCad cad;
  cad.has_geometry = [](int dim, int tag) {
    std::string type;
    gmsh_call("the CAD of the current model", [&] { gmsh::model::getType(dim, tag, type); });
    return type.rfind("Discrete", 0) != 0;
  };
  cad.closest = [](int dim, int tag, const Eigen::Matrix3Xd& x, Eigen::MatrixXd& params) {
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
    if (param.size() == static_cast<std::size_t>(dim * x.cols()))
      params = Eigen::Map<const Eigen::MatrixXd>(param.data(), dim, x.cols());
    return y;
  };
  return cad;
}

}  // namespace homesh::gmsh_adapter
