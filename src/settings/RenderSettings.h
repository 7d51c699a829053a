#pragma once
#include "settings/Choices.h"

#include <cstdint>

namespace settings {

// Every setting that trades accuracy for time, and the environment switch: the SETTING rows
// of settings/Options.def, which say for each what it is, its default, its option and
// whether files record it and the shader reads it (settings/SettingsTable.h). Changing one
// never recompiles, but for those that shape the shader's code (variant, exactGeometry and
// the three below).
struct RenderSettings {
#define SECTION(title)
#define OPTION(field, ...)
#define SETTING(Type, field, defaultValue, ...) Type field = defaultValue;
#include "settings/Options.def"
#undef SECTION
#undef OPTION
#undef SETTING

    // Not options: what the program asks of the shader for its own ends.
    // The shader reads the environment's kind from a uniform instead of building it in, so
    // that environmentLight can change without a recompile (the window's panel).
    bool switchableEnvironment = false;
    // Count work instead of light (ShaderBuild::profileCounters), for bench_throughput.
    bool profileCounters = false;
    // March boxes, cylinders and disks (ShaderBuild::marchBoxesCylindersAndDisks), for
    // tests of the sphere tracer against exact intersection.
    bool marchBoxesCylindersAndDisks = false;
};

}  // namespace settings
