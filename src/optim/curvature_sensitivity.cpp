#include "optim/curvature_sensitivity.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "element/quadrature.h"
#include "optim/ideal_element.h"
#include "optim/rank_correlation.h"
#include "quality/distortion.h"

namespace homesh {
namespace {

// Position of each measure in the ordering, 1 = first; a tied group shares
// the mean of its positions.
std::map<std::string, double> positions(const Ordering& ordering) {
  std::map<std::string, double> pos;
  int next = 1;
  for (const auto& group : ordering) {
    const double mean = next + 0.5 * (static_cast<double>(group.size()) - 1.0);
    for (const std::string& name : group) pos[name] = mean;
    next += static_cast<int>(group.size());
  }
  return pos;
}

}  // namespace

Eigen::Matrix2Xd curved_edge_element(double chi) {
  Eigen::Matrix2Xd X = equilateral_element(2);
  X(1, 3) = chi;
  return X;
}

double curvature_distortion(const Measure& m, double chi, const DistortionSettings& s) {
  const ElementSampling rule(2, triangle_quadrature(s.quadrature_degree));
  return distortion_function(m, rule, curved_edge_element(chi), s.r, s.reference);
}

std::vector<std::pair<std::string, double>> curvature_distortions(double chi,
                                                                  const DistortionSettings& s) {
  std::vector<std::pair<std::string, double>> values;
  for (const Measure& m : measures()) values.emplace_back(m.name, curvature_distortion(m, chi, s));
  return values;
}

Ordering rank_by_value(const std::vector<std::pair<std::string, double>>& values,
                       double relative_tie) {
  std::vector<size_t> order(values.size());
  for (size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return values[a].second > values[b].second; });
  std::vector<std::vector<size_t>> groups;
  double group_value = 0;
  for (size_t i : order) {
    const double value = values[i].second;
    if (!groups.empty() && std::abs(group_value - value) <= relative_tie * std::abs(group_value)) {
      groups.back().push_back(i);
    } else {
      groups.push_back({i});
      group_value = value;
    }
  }
  Ordering ordering;
  for (std::vector<size_t>& group : groups) {
    std::sort(group.begin(), group.end());  // ties in input order
    ordering.emplace_back();
    for (size_t i : group) ordering.back().push_back(values[i].first);
  }
  return ordering;
}

double ordering_correlation(const Ordering& a, const Ordering& b) {
  const auto pa = positions(a), pb = positions(b);
  std::vector<double> xa, xb;
  for (const auto& [name, position] : pa) {
    const auto it = pb.find(name);
    if (it == pb.end()) continue;
    xa.push_back(position);
    xb.push_back(it->second);
  }
  return spearman(Eigen::Map<Eigen::VectorXd>(xa.data(), static_cast<Eigen::Index>(xa.size())),
                  Eigen::Map<Eigen::VectorXd>(xb.data(), static_cast<Eigen::Index>(xb.size())));
}

std::string to_string(const Ordering& ordering) {
  std::string text;
  for (const auto& group : ordering) {
    if (!text.empty()) text += " > ";
    for (size_t i = 0; i < group.size(); ++i) text += (i ? " = " : "") + group[i];
  }
  return text;
}

}  // namespace homesh
