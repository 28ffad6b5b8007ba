// Every tuning constant of the stereo VO, in one place. They were chosen
// once from the physics of the problem and the library's behaviour (noted
// at each), checked on the rendered scenarios at 40x30, 80x60 and 160x120
// and on the real slider_depth; none was fitted to one recording.
// Sizes that depend on the image (feature spacing, KLT window, pyramid
// depth) are derived from the working size in klt_frontend.cpp.
#pragma once
#include "lumavel/host/settings.hpp"

namespace lumavel::host::vo {

struct VoParams {
  // --- features (Shi-Tomasi corners in cam0, tracked by pyramidal KLT) ---
  // Up to a hundred or so agreeing tracks average KLT's noise down about
  // 10x; more costs time for little. (At 40x30 the texture floor and the
  // corner spacing leave 20-80 tracks anyway.)
  int max_features = 150;
  // Re-detect when fewer tracks than this fraction of max_features survive:
  // waiting for a few losses keeps tracks long (their stereo depth is then
  // re-measured every frame anyway), waiting longer starves the solver.
  double redetect_fraction = 0.7;
  // goodFeaturesToTrack's relative quality: low, because low-resolution
  // frames have few strong corners and KLT tracks edges of 2-D texture well.
  double corner_quality = 0.01;
  // Absolute texture floor: the smaller eigenvalue of the mean structure
  // tensor over the KLT window, as a gradient in gray levels per pixel.
  // Cheap sensors have 1-3 gray levels of noise; pure Gaussian noise reads
  // 0.4 (sigma 1), 0.75 (sigma 2, at most 1.1) and 1.1 (sigma 3, at most
  // 1.7) here, and its "corners" would be tracked as motion. 2.5, about 1.5x
  // the worst noise reading: untextured and dark frames raise the
  // low-texture bit instead of producing V.
  double min_gradient = 2.5;

  // --- tracking ---
  // Forward-backward consistency of every KLT track (temporal and stereo),
  // in working pixels: 10-30x the accuracy KLT reaches on these images
  // (0.01-0.03 px), far below a mismatch.
  double max_forward_backward_px = 0.3;
  // Stereo matches must lie on the epipolar line of the calibrated rig
  // within this (Sampson distance, working pixels): the calibration error of
  // a rig given in sensor.yaml plus matching noise.
  double max_epipolar_px = 1.0;
  // Stereo depth is resolved to about 0.1 px of disparity: at 40x30 (f about
  // 43 px) 430 baselines. A point triangulated beyond 1000 baselines (both
  // cameras delivering one image, a flat far view) cannot fix the scale of a
  // motion: it is dropped (with none left, V is held, low-texture bit).
  double max_depth_baselines = 1000;
  // KLT stopping rule: a step below 0.001 px, at most 30 iterations. The
  // motion is only 0.1-0.6 px per frame at 40x30, so OpenCV's default
  // (0.01 px) is coarse: it cost the real slider at h = 8 cm and 40x30
  // 0.75 points of E (5.34 % instead of 4.59 %), elsewhere within 0.1 point,
  // for about 5 % less time.
  double klt_epsilon_px = 1e-3;
  int klt_iterations = 30;

  // --- motion (translation with the rotation fixed by the gyro) ---
  // A track is an inlier when its reprojection error in both cameras is
  // below this, in working pixels: a lost track errs by a pixel or more.
  double inlier_px = 0.5;
  // The refinement tightens the threshold to 3x the median residual, but
  // not below this: KLT's accuracy on real images (rendered ones reach
  // 0.01 px and would reject good tracks for nothing).
  double inlier_floor_px = 0.05;
  // Fewer inliers than this: no measurement, V held, low-texture bit.
  int min_inliers = 8;

  // --- output filter: the same first-order filter and time constant as
  // lumavel's observer (V <- V + (d/dt - V) dt / (tau + dt)), so both trade
  // noise for lag alike and the comparison is of the measurements.
  double tau = EstimatorSettings{}.tau;
  // Longer frame gaps restart the filter from the next measurement (as
  // lumavel's max_gap); a frame gap is flagged beyond 1.5 frame periods.
  double max_gap = EstimatorSettings{}.max_gap;
  // A gyro interval longer than this over a frame interval is a gyro gap.
  double gyro_gap = EstimatorSettings{}.gyro_gap;
  // Frames darker than this mean gray level carry no image: no-light bit.
  double no_light_mean = 1.0;
};

}  // namespace lumavel::host::vo
