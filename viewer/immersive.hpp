#pragma once
// `strata view SCENE --immersive --trace FILE`: the camera is driven by a recorded head-pose
// trace played in real time, through two-step prediction and image deflection (issue 4):
//  1. frame start t0: the predictor has been fed every trace sample due by t0 (trace time runs
//     with the wall clock, looping); it predicts the pose at the expected display time
//     t0 + (measured start-to-display time) + extra latency, and the frame is rendered there;
//  2. after rendering t1: the samples due since are fed, the pose is predicted again for
//     t1 + (measured re-read-to-display time) + extra latency, and the finished image is
//     deflected (core/render/deflection_warp: shift or homography) from pose 1 to pose 2;
//  3. after the swap (taken as the display time) the true pose there is read from the truth
//     trace and every predictor x deflection combination is scored (tracking::viewingError):
//     all predictors run side by side on the same samples, the selected one drives the view.
// The trace's world frame is placed at the scene's default camera (the trace's identity pose
// shows the default view; trace positions move the eye relative to the first sample, metres
// as scene units). The truth trace is FILE with "-measured" replaced by "-truth" when such a
// file exists, else the measured trace interpolated (then the error shows prediction only).
// Side-by-side stereo: two eyes IPD apart along the head's right axis, each in half the window.
#include "view_app.hpp"
#include "window_loop.hpp"

#include "scene/scene.hpp"

namespace strata {

// Reads and checks the traces and the immersive choices, before any window opens, and returns what
// makes the immersive mode of the window loop (viewer/window_loop.hpp) once the window exists.
// Throws std::runtime_error without --trace, on a malformed trace (file:line), on an unknown
// predictor or deflection, and when the tracking library was not built.
WindowModeFactory immersiveMode(const ViewOptions& options, Scene scene);

}  // namespace strata
