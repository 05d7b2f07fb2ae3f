#pragma once
// Assembling the lower triangle of a symmetric system of 3 unknowns a node
// (the 3D elastic analogy) straight into compressed column storage: the
// pattern from the elements' nodes, then each element matrix added in place.
// Triplets cost 16 bytes an element entry and a sort: at p = 4 on 1.5e4
// tetrahedra, 5.6e7 triplets (0.9 GB) and 3.5-4.9 s, for 3.7e7 entries.
#include <Eigen/Core>
#include <Eigen/SparseCore>

namespace homesh {

/// The lower triangle's pattern (values zero) of the system coupling, for each
/// element (a column of `unknown`: its nodes' unknown node numbers, -1 for a
/// node that is not one), every pair of its unknown nodes: 3 n by 3 n for n =
/// `nodes`, unknown node u's components at 3 u, 3 u + 1, 3 u + 2. A column's
/// first entry is its diagonal.
Eigen::SparseMatrix<double> block_lower_pattern(const Eigen::MatrixXi& unknown, int nodes);

/// Adds the lower triangle of the element matrix Ke (3 k by 3 k, component i of
/// local node a at 3 a + i) into A, which has block_lower_pattern's pattern
/// for an `unknown` with this element's column u.
void add_block_lower(Eigen::SparseMatrix<double>& A, const Eigen::Ref<const Eigen::VectorXi>& u,
                     const Eigen::MatrixXd& Ke);

/// Rows [first, first + count) of the full symmetric system (both triangles)
/// that block_lower_pattern's lower triangle stands for, as a count by 3 n
/// row-major pattern (values zero): a process's share of a distributed solve
/// (fem/petsc_solver.h), which needs no other rows.
Eigen::SparseMatrix<double, Eigen::RowMajor> block_rows_pattern(const Eigen::MatrixXi& unknown,
                                                                int nodes, int first, int count);

/// Adds the element matrix Ke's entries in rows [first, first + A.rows()) into
/// A, which has block_rows_pattern's pattern for this `first`.
void add_block_rows(Eigen::SparseMatrix<double, Eigen::RowMajor>& A, int first,
                    const Eigen::Ref<const Eigen::VectorXi>& u, const Eigen::MatrixXd& Ke);

}  // namespace homesh
