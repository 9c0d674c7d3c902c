// hapstab/numeric/eigen_decompositions.hpp -- Eigen's dense decompositions over double and
// std::complex<double>, compiled once.
//
// Each unit that constructs an Eigen::EigenSolver<MatrixXd> (or a JacobiSVD, an LLT, ...) would
// otherwise instantiate and optimise the whole decomposition again: in lmi/passivity_level.cpp
// they were 3/4 of the unit's compile time (docs/build.md). Here they are declared `extern
// template`; numeric/eigen_eigensolvers.cpp, eigen_factorizations.cpp and eigen_svds.cpp hold the one
// explicit instantiation of each. cmake/pch.hpp includes this header, so every unit built on the precompiled
// header sees the declarations before its first use. A call whose argument is an expression, not a plain
// MatrixXd/MatrixXcd, still instantiates compute() for that expression type in its own unit:
// pass a matrix. Nothing here changes a result: the same code, compiled in one place.
#pragma once
#include <Eigen/Cholesky>
#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <Eigen/SVD>

// HAPSTAB_EIGEN_*(extern) declare them; numeric/eigen_*.cpp pass nothing and define them (three
// units, not one: compiled in parallel, none is the build's longest). A member template,
// compute(const EigenBase<InputType>&, ...), is not part of its class's explicit instantiation,
// so it is listed with InputType = the matrix type and its parameter list, PARAMS.
#define HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, CLASS, MATRIX, PARAMS) \
  KEYWORD template class Eigen::CLASS<Eigen::MATRIX>;               \
  KEYWORD template Eigen::CLASS<Eigen::MATRIX>& Eigen::CLASS<Eigen::MATRIX>::compute PARAMS;
#define HAPSTAB_EIGEN_EIGENSOLVERS(KEYWORD)                                      \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, EigenSolver, MatrixXd,                    \
                              (const Eigen::EigenBase<Eigen::MatrixXd>&, bool))  \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, ComplexEigenSolver, MatrixXcd,            \
                              (const Eigen::EigenBase<Eigen::MatrixXcd>&, bool)) \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, SelfAdjointEigenSolver, MatrixXd,         \
                              (const Eigen::EigenBase<Eigen::MatrixXd>&, int))   \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, SelfAdjointEigenSolver, MatrixXcd,        \
                              (const Eigen::EigenBase<Eigen::MatrixXcd>&, int))  \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, RealSchur, MatrixXd,                      \
                              (const Eigen::EigenBase<Eigen::MatrixXd>&, bool))  \
  KEYWORD template class Eigen::HessenbergDecomposition<Eigen::MatrixXd>;
#define HAPSTAB_EIGEN_FACTORIZATIONS(KEYWORD)                                                       \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, LLT, MatrixXd, (const Eigen::EigenBase<Eigen::MatrixXd>&))   \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, LLT, MatrixXcd, (const Eigen::EigenBase<Eigen::MatrixXcd>&)) \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, LDLT, MatrixXd, (const Eigen::EigenBase<Eigen::MatrixXd>&))  \
  HAPSTAB_EIGEN_DECOMPOSITION(KEYWORD, ColPivHouseholderQR, MatrixXd,                               \
                              (const Eigen::EigenBase<Eigen::MatrixXd>&))                           \
  KEYWORD template class Eigen::PartialPivLU<Eigen::MatrixXd>;                                      \
  KEYWORD template class Eigen::PartialPivLU<Eigen::MatrixXcd>;                                     \
  KEYWORD template class Eigen::FullPivLU<Eigen::MatrixXd>;                                         \
  KEYWORD template class Eigen::HouseholderQR<Eigen::MatrixXd>;                                     \
  KEYWORD template class Eigen::HouseholderQR<Eigen::MatrixXcd>;
#define HAPSTAB_EIGEN_SVDS(KEYWORD)                         \
  KEYWORD template class Eigen::JacobiSVD<Eigen::MatrixXd>; \
  KEYWORD template class Eigen::JacobiSVD<Eigen::MatrixXcd>;

HAPSTAB_EIGEN_EIGENSOLVERS(extern)
HAPSTAB_EIGEN_FACTORIZATIONS(extern)
HAPSTAB_EIGEN_SVDS(extern)
