#pragma once
// Shared fixtures of the quality-measure tests: reproducible random Jacobians,
// rotations, straight-sided and curved elements, and the thesis tables read
// from HOMESH_REFERENCE_DIR.
#include <Eigen/Core>
#include <Eigen/LU>
#include <cmath>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "element/reference_nodes.h"

namespace homesh::test {

inline Eigen::Matrix2d rotation(double angle) {
  Eigen::Matrix2d R;
  R << std::cos(angle), -std::sin(angle), std::sin(angle), std::cos(angle);
  return R;
}

/// `count` random W with det W > 0: R(a) diag(s1, s2) R(b) with singular values
/// log-uniform in [e^-3, e^3], then generic matrices with entries in [-2, 2].
inline std::vector<Eigen::Matrix2d> random_valid_jacobians(int count, unsigned seed = 7) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> angle(0.0, 2.0 * M_PI), log_s(-3.0, 3.0), entry(-2, 2);
  std::vector<Eigen::Matrix2d> out;
  while (static_cast<int>(out.size()) < count / 2) {
    out.push_back(rotation(angle(gen)) *
                  Eigen::Vector2d(std::exp(log_s(gen)), std::exp(log_s(gen))).asDiagonal() *
                  rotation(angle(gen)));
  }
  while (static_cast<int>(out.size()) < count) {
    Eigen::Matrix2d W;
    W << entry(gen), entry(gen), entry(gen), entry(gen);
    if (W.determinant() > 1e-6) out.push_back(W);
  }
  return out;
}

/// Nodes (2 by (p+1)(p+2)/2, Gmsh order) of the straight-sided order-p
/// triangle with corners a, b, c.
inline Eigen::Matrix2Xd straight_element(int p, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                         const Eigen::Vector2d& c) {
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  Eigen::Matrix2Xd X(2, uv.cols());
  for (int k = 0; k < uv.cols(); ++k) {
    X.col(k) = a + uv(0, k) * (b - a) + uv(1, k) * (c - a);
  }
  return X;
}

/// The unit equilateral triangle (0,0), (1,0), (1/2, sqrt(3)/2) of order p.
inline Eigen::Matrix2Xd equilateral_element(int p) {
  return straight_element(p, {0.0, 0.0}, {1.0, 0.0}, {0.5, std::sqrt(3.0) / 2.0});
}

/// A valid curved element of order p: a scalene triangle whose non-corner
/// nodes are moved by reproducible offsets of size up to `amplitude`.
inline Eigen::Matrix2Xd curved_element(int p, double amplitude = 0.06, unsigned seed = 3) {
  Eigen::Matrix2Xd X = straight_element(p, {0.1, -0.2}, {1.3, 0.1}, {0.4, 1.0});
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> offset(-amplitude, amplitude);
  for (int k = 3; k < X.cols(); ++k) X.col(k) += Eigen::Vector2d(offset(gen), offset(gen));
  return X;
}

/// The element X of order p relabelled cyclically: new corner i is old corner
/// i+1 (mod 3), every node renumbered in Gmsh order for the new corners.
inline Eigen::Matrix2Xd relabel_cyclic(const Eigen::Matrix2Xd& X, int p) {
  const Eigen::Matrix2Xd uv = reference_nodes(p);
  Eigen::Matrix2Xd Y(2, X.cols());
  for (int k = 0; k < uv.cols(); ++k) {
    // Barycentric (l0, l1, l2) of the new node is (l1, l2, l0) of the old one.
    const Eigen::Vector2d old_uv(1.0 - uv(0, k) - uv(1, k), uv(0, k));
    int match = -1;
    for (int j = 0; j < uv.cols(); ++j) {
      if ((uv.col(j) - old_uv).norm() < 1e-12) match = j;
    }
    if (match < 0) throw std::logic_error("relabel_cyclic: node not on the lattice");
    Y.col(k) = X.col(match);
  }
  return Y;
}

/// A thesis table of 0/1 flags from HOMESH_REFERENCE_DIR: rows keyed by the
/// first column, values by the header names; lines starting with '#' skipped.
inline std::map<std::string, std::map<std::string, std::string>> read_reference_table(
    const std::string& file) {
  std::ifstream in(std::string(HOMESH_REFERENCE_DIR) + "/" + file);
  if (!in) throw std::runtime_error("cannot read reference table " + file);
  std::vector<std::string> header;
  std::map<std::string, std::map<std::string, std::string>> table;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (header.empty()) {
      header = cells;
      continue;
    }
    for (size_t i = 1; i < cells.size() && i < header.size(); ++i) {
      table[cells[0]][header[i]] = cells[i];
    }
  }
  return table;
}

}  // namespace homesh::test
