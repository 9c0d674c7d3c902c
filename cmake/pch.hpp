// The heavy headers nearly every translation unit includes, precompiled once (cmake/pch.hpp).
#pragma once
#include <algorithm>
#include <complex>
#include <map>
#include <string>
#include <vector>
#include <Eigen/Core>
#include <boost/multiprecision/gmp.hpp>
#include <boost/multiprecision/mpfi.hpp>
#include <boost/multiprecision/mpfr.hpp>
// Eigen's decompositions over double and complex<double>: declared extern, compiled once in numeric/
#include "../toolbox/hapstab/numeric/eigen_decompositions.hpp"
