// The one explicit instantiation of each of numeric/eigen_decompositions.hpp's HAPSTAB_EIGEN_FACTORIZATIONS.
#include "hapstab/numeric/eigen_decompositions.hpp"

HAPSTAB_EIGEN_FACTORIZATIONS()
