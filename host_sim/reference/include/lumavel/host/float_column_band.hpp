// Twin of the core's column band (ColumnBand in column_profile.hpp, built by
// build_band in kernel_bank.cpp): the elevation band every column sums (one
// for both cameras, its edge rows weighed in 1/256 as the core's are, so
// that both engines sum the same pixels with the same weights), and each
// camera's cos(a_u) weight of the kernel tables.
#pragma once
#include <Eigen/Dense>
#include <cstdint>

#include "lumavel/host/settings.hpp"

namespace lumavel::host {

struct FloatColumnBand {
  bool banded = false;
  Eigen::MatrixXd row_weight;  // height x width: each pixel's weight in its column's sum
  Eigen::VectorXd rows;        // per column: the rows it sums (row_weight's column sums)
  Eigen::VectorXd cos[2];      // cos(a_u) per column: the tables' weight (1 when not banded)
};

// Twin of column_cos_q30: each column's elevation scale, the lens table's
// where there is one, else cos(a_u), a_u the yaw of column u's centre (the
// mean of its edges, width + 1 of them) from the axis; 0 at or past 90 deg.
Eigen::VectorXd float_column_cos(const CameraModel& cam, const Eigen::VectorXd& edges);

// edges: each camera's column edge yaws (width + 1).
FloatColumnBand build_float_column_band(const EstimatorSettings& s, const Eigen::VectorXd (&edges)[2]);

}  // namespace lumavel::host
