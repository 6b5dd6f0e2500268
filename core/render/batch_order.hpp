#pragma once
// Batches nearest first. A batched order (GpuScene::opaqueObjectsBatched and
// transparentObjectsBatched) holds runs of objects that one instanced draw can take; this puts
// the runs in order of their nearest member along the view, each run kept whole and in its own
// order, so batching is unchanged.
//
// Why: a pass that tests depth before its shader (the opaque pass, every peel after the count)
// rejects what lies behind what it has already drawn, so drawing near things first leaves less
// to shade. f2b on 16 parallel layers at 256x256 on llvmpipe: 46 ms drawn nearest first, 68 ms
// drawn farthest first; the naive probe draws nearest first. The result does not depend on the
// order (the depth test keeps the nearest; among equal depths the earlier draw, which a technique
// that is not coplanarity-aware leaves to chance anyway).
#include <functional>
#include <vector>

namespace strata {

// `sameRun(a, b)`: whether b may join a's run (GpuScene::drawObjects's rule); `nearest(o)`: the
// smallest view depth of object o's bounds. Runs tie by their first position: stable.
void orderRunsNearestFirst(std::vector<int>& order, const std::function<bool(int, int)>& sameRun,
                           const std::function<float(int)>& nearest);

}  // namespace strata
