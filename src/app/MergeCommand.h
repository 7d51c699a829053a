#pragma once
#include "app/CommandLine.h"

namespace app {

// raytracer merge OUT.exr IN.exr... : combines renders of one scene, size and settings into
// the render that holds all their samples (film/Accumulation.h), or refuses with one line
// and writes nothing. Returns the exit status; errors propagate as exceptions whose message
// is the line to show.
int runMerge(const MergeRequest& request);

}  // namespace app
