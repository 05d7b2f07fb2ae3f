#include "study/gallery_report.h"

#include <fmt/format.h>

#include <Eigen/LU>
#include <cmath>

#include "element/lagrange_basis.h"
#include "element/reference_nodes.h"
#include "optim/gallery.h"
#include "quality/element_sampling.h"
#include "quality/jacobian_bounds.h"

namespace homesh {
namespace {

constexpr int kSampleLattice = 24;  // 325 points: smooth colour maps, curved outlines

}  // namespace

std::string report_gallery(const StudyInputs& in, const StudyOutput& out) {
  const std::vector<GalleryElement> gallery = read_gallery(in.gallery);
  const double ideal_J = std::sqrt(3.0) / 2.0;
  const Eigen::Matrix2Xd uv = reference_nodes(kSampleLattice);
  std::string csv = "element,order,kind,index,u,v,x,y,omega\n";
  std::string md = fmt::format(
      "## Gallery T1-T12 (Section 3.7.2, Fig 3.12)\n\n"
      "Constructed from the thesis's descriptions: `{}` (comments say how). Picture: "
      "`gallery.png`. det J is certified positive on every element (Bezier bounds).\n\n"
      "| element | order | min det J / ideal (certified bound) | max det J / ideal | description "
      "|\n"
      "|---|---|---|---|---|\n",
      in.gallery);
  for (const GalleryElement& e : gallery) {
    const Eigen::Matrix2Xd nodes_uv = reference_nodes(e.order);
    for (int k = 0; k < e.nodes.cols(); ++k) {
      csv += fmt::format("{},{},node,{},{},{},{},{},\n", e.name, e.order, k, number(nodes_uv(0, k)),
                         number(nodes_uv(1, k)), number(e.nodes(0, k)), number(e.nodes(1, k)));
    }
    const LagrangeBasis basis(e.order);
    const ElementSampling samples(e.order, uv);
    for (int k = 0; k < uv.cols(); ++k) {
      const Eigen::Vector2d x = e.nodes * basis.values(uv.col(k));
      const double omega = samples.jacobian(e.nodes, k).determinant() / ideal_J;
      csv += fmt::format("{},{},sample,{},{},{},{},{},{}\n", e.name, e.order, k, number(uv(0, k)),
                         number(uv(1, k)), number(x[0]), number(x[1]), number(omega));
    }
    const JacobianBounds b = jacobian_bounds(e.nodes, e.order);
    md += fmt::format("| {} | {} | {:.3f} | {:.3f} | {} |\n", e.name, e.order,
                      b.min_lower / ideal_J, b.max_upper / ideal_J, e.description);
  }
  out.write("gallery_samples.csv", csv);
  return md + "\n";
}

}  // namespace homesh
