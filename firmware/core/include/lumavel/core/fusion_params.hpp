// Parameters of the time-of-flight measurement and of its fusion with the
// differential observer: one source of truth for the firmware core (which
// builds its integer constants from these values at compile time) and the
// double-precision twin (host_sim/reference). Each value says what it means
// physically; none is tuned to one recording (docs/design.md tells how they
// were chosen and what they were checked on).
#pragma once

namespace lumavel::params {

// ---- time of flight (time_of_flight.hpp) ----
// A match lies on the lead camera's path through kernel space between two of
// its frames; its residual distance from that path must be small against the
// step between the two frames ...
constexpr double kTofMaxPathResidual = 0.3;
// ... or, for a track that has held on that gate for kTofWindowGateFrames,
// against its window: the residual, were it all along the path, would move
// tau by at most this fraction of tau (a segment's step in time is its span).
// On a long window the lead's view changes little per frame (a slow pass, a
// far scene) while the noise and the cameras' difference do not shrink with
// it, so the step's gate alone dropped a held track on many frames; where tau
// is a frame or two, the step's gate is the wider and stands.
constexpr double kTofMaxTauShift = 0.1;
// The window's gate in steps never passes this (beyond 2 the motion gate below
// decided every candidate: the same figures); it bounds the integer products.
constexpr double kTofMaxPathResidualLong = 4.0;
// Frames a track must have held on the step's gate before the window's
// applies. Never for an acquisition: a periodic near wall (the synthetic rig at
// 0.13-0.17 m) offers matches at several taus, and with the window's gate
// aliases were taken up and then held (7 of 16 runs 20-120 % off, against
// 0.8-1.6 % with the step's gate; with it for any held track, 1 of 16).
constexpr int kTofWindowGateFrames = 6;
// The lead's path bends between its frames: a point on the chord between two
// of them stands for a later or earlier time than its fraction along it. That
// fraction is moved by the path's second difference (docs/design.md,
// "Search"), by at most this share of the segment's span: in clutter, and
// where one camera's auto-exposure steps, the second difference is noise
// (unheld: near clutter with per-camera auto-exposure +11 %).
constexpr double kTofChordMaxShift = 0.02;
// Under a frame (the newest segment) the lead moves several h between its
// frames and the chord models its path poorly (streets at 30 Hz: h / tau
// 0.65-2 V). There the path is taken as the cubic through the lead's last
// three frames whose change over the trail's lag at the older one is that
// frame's stereo difference (docs/design.md, "Search"); its point is taken
// where its residual is within kTofCubicTake of the step, blended with the
// chord's up to kTofCubicBlend, the chord's beyond; within kTofCubicMaxMove
// of the chord's fraction, kTofCubicEnds from the segment's ends. Its timing
// sigma is kTofCubicSigma of its residual's, blended as the point.
constexpr double kTofCubicTake = 0.1;
constexpr double kTofCubicBlend = 0.3;
constexpr double kTofCubicMaxMove = 0.5;
constexpr double kTofCubicEnds = 0.02;
constexpr double kTofCubicSigma = 0.5;
// Its search: a grid of this many steps over the segment, then this many
// parabolas about the grid's best point, each this many times narrower
// (narrower ones parted the twins where tau is a tenth of a frame: there the
// costs differ by less than their last bits; with four, by 1.2 times
// FixedVsFloat's allowance).
constexpr int kTofCubicGrid = 16;
constexpr int kTofCubicParabolas = 2;
constexpr int kTofCubicShrink = 8;
// ... and against the trail camera's own change since its previous frame
// (so that a still or slowly changing view cannot match anything).
constexpr double kTofMaxResidualVsMotion = 1.0;
// A closest point just beyond a segment's end, by up to this fraction of the
// segment's step (projected), is taken as that end (the frame itself): the
// two engines' sums differ in their last bits, and a point on a frame must
// not fall off both segments in one engine and onto one in the other
// (`FixedVsFloat.At160x120` split so for a frame at 1/65536). A tie-breaker,
// not a search: at 1/64 and 1/1024 more points were taken, and the day
// soak's twins parted by 5.1 % of the speed after their splits (bound 5 %).
constexpr double kTofVertexSlack = 1.0 / 16384;
// Rotation between the two sightings, in units of the narrowest kernel's
// sigma. The matching turns the trail's F back with the mean of the two
// sightings' slopes (a trapezoid: what it leaves is (dtheta / sigma)^3 / 12
// of F's third derivative, 1 % at 0.5). Measured on arcs past walls at
// 0.5-2.5 m (R 0.5-3 m, 0.25-1.5 m/s, 50 deg views; docs/design.md): at 0.25
// no arc under R = 4.4 m had a time of flight, and beside a wall at 0.5 m the
// differential alone read V 40 % low (E 46-52 % on R = 3 m); at 0.5 those
// arcs 6.6-12 % and no render worse by more than 4 % of its E; at 0.75 and
// beyond, arcs of R 0.5-2 m 16-95 % worse (the gates let the error through).
constexpr double kTofMaxRotationSigma = 0.5;
// The tracked time of flight may move by this many frame periods, or by this
// fraction of itself, from one frame to the next.
constexpr double kTofTrackGateFrames = 2.0;
constexpr double kTofTrackGateFraction = 0.3;
// Frames without a match before the track is dropped, and consistent frames
// needed to take up a new one.
constexpr int kTofTrackMisses = 5;
constexpr int kTofAcquireFrames = 3;
// Frames with no candidate at all that such a run bridges, in a row: among
// clutter and between cameras that differ, the match comes and goes frame by
// frame, and a frame without one says nothing against the run (a candidate at
// another tau still ends it). Near clutter with mismatched cameras acquired
// 0.3 s later without it (docs/design.md, "Search").
constexpr int kTofAcquireGapFrames = 2;
// A new track must agree with the fused velocity to this fraction (a periodic
// scene offers matches at wrong times too), unless the rig is this slow (m/s).
constexpr double kTofAcquireAgreement = 0.3;
constexpr double kTofAcquireMinSpeed = 0.1;
// Longest time of flight used (s): beyond it the window mean lags a varying V.
constexpr double kTofMaxTau = 0.6;
// A track lost this long (s) while no candidate agrees with the hints is
// looked for unguided as well (both directions, every usable tau), and taken
// after this many consistent frames (twice the guided count: nothing vouches
// for it but its own consistency). Where a failed differential holds the
// fused V wrong, no candidate agrees with it, and the right track could
// never be taken up again (near clutter at h = 12 cm: V 0.25 m/s for 2.5 s of
// a 0.7 m/s pass, no time of flight). A history in which no track has held
// yet counts as lost long from its start (nothing has vouched for the hints);
// a hint against the images' direction of travel guides nothing, and with no
// other the search is unguided from the frame it is (docs/design.md, "Tracker").
constexpr double kTofLostTime = 0.5;
constexpr int kTofLostAcquireFrames = 6;

// ---- the image's direction of travel (image_direction.hpp) ----
// Each camera's image motion that the gyro's turn does not explain, as a yaw
// rate (rad/s), smoothed over this time (s) ...
constexpr double kImageDirectionTau = 0.2;
// ... states a direction only beyond this rate (an unlearned gyro offset of a
// few deg/s reads as image motion; at rest the back-and-forth scenes' reading
// reached 0.22 rad/s at 0.05, none at 0.1 once it also passed the scatter
// below) ...
constexpr double kImageDirectionMinRate = 0.1;
// ... and beyond this many of its own scatter (its rms about the smoothed
// value, smoothed alike): at one, the slaloms of cameras that differ read the
// wrong direction on 2-8 frames; at two, none of 130 renders did.
constexpr double kImageDirectionSigmas = 2.0;
// Cameras that look within 30 deg of the travel (|sin| of their mean axis
// yaw below this) see too little of the travel's image motion: no direction.
constexpr double kImageDirectionMinLook = 0.5;
// An output faster than this (m/s) against a stated direction raises
// kStatusAgainstImages (at rest and through a reversal V is near 0 and
// the direction is not yet stated: none of 130 renders raised it).
constexpr double kImageDirectionFlagSpeed = 0.1;

// ---- fusion (velocity_fusion.hpp) ----
// The differential's residual ratio is tracked only while it moves: from
// this speed (m/s), its gain ramped in to full at the second (no step that
// two engines a hair either side of it would take apart) ...
constexpr double kFusionResidualMinSpeed = 0.05;
constexpr double kFusionResidualFullSpeed = 0.055;
// ... with this gain per frame.
constexpr double kFusionResidualGain = 0.3;
// The differential's relative uncertainty: a floor plus this much of the
// square root of its residual ratio, times the speed, plus an absolute floor
// (m/s); in quadrature with the uncertainty of the scale it is divided by.
// (The floor: on the paper's clean scenes the differential alone is within
// 0.2 % (E 0.22 % on paper_sim_aligned); at 0.5 % the noisier time of flight
// took a third of the weight there: the photo wall at 160x120, E 0.88 % ->
// 0.64 % with 0.2 % and the scale's term.)
constexpr double kFusionDiffFloor = 0.002;
constexpr double kFusionDiffPerResidual = 0.5;
constexpr double kFusionSpeedFloor = 0.003;
// The scale's term uses the speed up to this (m/s): beyond it, as at it.
constexpr double kFusionScaleTermMaxSpeed = 64.0;
// The time of flight's relative uncertainty is never taken below this, and is
// inflated by the normalised innovation it shows against a clean differential
// (tracked with this gain, bounded to [1, 100]): its timing uncertainty is an
// estimate, the innovations show what it really is on this scene.
constexpr double kFusionTofFloor = 0.01;
// Where the differential points against the time of flight's direction (which
// camera trails: a discrete fact of the match; taken as moved to the present
// by the fused rate, so that a window spanning a reversal does not hold the
// direction of its mean, and only where that stands clear of 0 by this many
// of its own sigmas) by more than this many of its own sigmas, it has failed
// (near texture aliasing can turn it over while its kernels still agree): the
// time of flight alone, and its scatter is not judged against it. (Near
// clutter: V -1.3 m/s for 1.2 s of a 0.7 m/s pass.)
constexpr double kFusionAgainstSigmas = 2.0;
// The time of flight is a mean over its window; the fusion moves it to the
// present by the fused rate, A tau / 2. That rate lags a change of
// acceleration (kFusionAccelTau) and is noisy, so the move counts as
// uncertain by this share of itself: the time of flight weighs less while
// the rig accelerates and its window is long (measured at 0, 0.5 and 1:
// docs/design.md, "Moving the window to the present").
constexpr double kFusionTofMoveShare = 0.5;
// Once it has so failed, it stays failed on the frames without a time of
// flight that follow (a track lost for a few frames while near texture still
// turns the differential over): V is held until the differential agrees again
// (the fused V's sign, or within kFusionAgainstSigmas of 0), for at most this
// long (s) since the last time of flight, and the time of flight's
// re-acquisition is guided by the fused V, not by the failed direct value.
// (Near clutter, mismatched cameras: a track lost for 3 frames let V follow
// the differential to -1.1 m/s, and a wrong-direction track guided by it held
// it there for 1 s of a 0.65 m/s pass.)
constexpr double kFusionFailedHold = 0.5;
// A track held through a miss (time_of_flight.hpp: fewer than
// kTofTrackMisses frames without a match) still constrains V: its last value,
// moved on by the fused rate, is weighed against the differential with its
// sigma grown to this many times its own per frame since the match (n frames
// missed: this times n + 1). (Near texture turns the differential for a frame
// or two while the track is still there: near clutter 3.47 -> 3.15 %, the
// slider at h = 8 cm 2.78 -> 2.40 %; 1 instead of 2: near clutter 3.07 %, but
// back and forth +1.8 % and the trolley +1.4 %.)
constexpr double kFusionCoastSigmaGrowth = 2.0;
constexpr double kFusionTofInflationGain = 0.02;
constexpr double kFusionTofInflationMax = 100.0;
// The differential's scale is learned from the time of flight where its
// residual ratio is small against this (a clean differential), as a random
// walk of this variance per second (never above the prior's), from
// measurements whose variance is 4 max(sig, kFusionTofFloor)^2 times the
// frames in the window (consecutive frames share most of their window: one
// independent measurement per tau) ...
constexpr double kFusionScaleMaxResidual = 0.02;
// ... and where V changes little over the window against this fraction
// (during an acceleration the direct values lag it, which reads as a scale).
// Each ratio q to its limit multiplies that variance by 1 + q^4; beyond
// kFusionScaleSoftCut the measurement is not used at all.
constexpr double kFusionScaleMaxChange = 0.01;
// ... and where the window is long against a frame interval (q = this many
// intervals over the window, weighed as the other two): a window inside one
// frame step is an interpolation along a chord of the lead's path (off by up
// to 12 % at 8 m/s past a wall at 3 m) over a fraction of one frame's
// differential travel (the scale was learned 2-3 % high there once the
// differential itself was right).
constexpr double kFusionScaleShortFrames = 2.0;
// ... and where the rig turned little over the window: the gyro's rotation
// summed frame by frame in absolute value (a slalom's change of direction
// does not cancel), in units of the narrowest kernel's sigma, weighed as the
// three above. The differential's rotation term is good to a few percent
// (the columns against the texture: docs/design.md), so while turning it
// errs by a few percent of the turn's share of the image motion, with the
// turn's sign: a scale learned there is that error, and the next turn the
// other way doubles it (the gyro-offset slalom, +-0.27 rad/s along a wall at
// 2 m: a scale of 1.018 learned where one arc met the next, then -0.014 m/s
// through the following 4 s of turning; -0.004 with this).
constexpr double kFusionScaleMaxTurnSigma = 0.05;
constexpr double kFusionScaleSoftCut = 3.0;
constexpr double kFusionScaleWalk = 1e-4;
constexpr double kFusionScaleStartVar = 1e-3;  // the prior: 1 +- 3 %
constexpr double kFusionScaleMin = 0.5, kFusionScaleMax = 2.0;
// Output smoothing (s); without a time of flight it slows by 1 + residual/0.05.
constexpr double kFusionTau = 0.02;
constexpr double kFusionSlowResidual = 0.05;
// The observer's V lags a ramp by its time constant times the rate A: that
// lag, c = tau_obs A from the fused V's rate, is added back to the
// differential in the measure it stands out of its own noise (weight
// c^2 / (c^2 + n^2 var_c), var_c from the direct values' scatter and the
// differential's floor kFusionDiffFloor, n this many sigmas) and never beyond the lag the observer shows, 2 (V_half - V) with
// V_half the same observer at half its time constant (A outlasts a step by
// tau_a; the observer's lag does not). Trolley L1 6.19 -> 4.20 %, back and
// forth E 26.71 -> 23.98 % at 40x30; added in full, without the weight, the
// noisy scenes lost 10-14 %; the shown lag alone (lag-free, but as noisy as
// V_half) lost 6-19 % on the near clutter, the mismatched wall and the dark
// frames. The term is then scaled by (tau_obs + dt/2 + kFusionTau) / tau_obs:
// the same ramp lags by the direct values' half interval and by the output's
// own smoothing (trolley L1 4.20 -> 3.55 % at 40x30, 4.07 -> 3.44 % at
// 160x120).
constexpr double kFusionLagSigmas = 3.0;
// The rate of change of V, for the window's lag (tau / 2): its smoothing (s)
// and bound (m/s^2); the direct values' scatter is smoothed as the rate.
constexpr double kFusionAccelTau = 0.3;
constexpr double kFusionAccelMax = 10.0;
// The window's move to the present (and a held track's coast) takes a faster
// rate where the differential is clean: smoothed over kFusionMoveAccelTau (s)
// at a residual up to kFusionScaleMaxResidual, the kFusionAccelTau rate alone
// from kFusionMoveAccelResidual on, linear between. A clean differential's
// rate is mostly not noise, and a start or a stop outruns the slow rate (the
// trolley's L1 at 160x120 3.06 -> 2.81 %; at 0.15 s 2.68 %, but a steady
// synthetic pass's worst error +13 %); among near clutter (residual 0.2 and
// more) the rate carries the differential's aliasing, and the fast rate
// alone lost 4-11 % there (docs/design.md, "Moving the window to the
// present"). Not while the differential stands failed against the time of
// flight (its residual does not show that).
constexpr double kFusionMoveAccelTau = 0.2;
constexpr double kFusionMoveAccelResidual = 0.1;
static_assert(kFusionMoveAccelResidual > kFusionScaleMaxResidual, "the blend runs from the clean residual up");

}  // namespace lumavel::params
