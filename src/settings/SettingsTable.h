#pragma once
// The render settings' rows of settings/Options.def, bound to RenderSettings: what the
// command line, the files' metadata, the uniforms' upload and the shader's declarations are
// derived from.
#include "settings/OptionTable.h"
#include "settings/RenderSettings.h"

#include <string>
#include <vector>

namespace settings {

using SettingRow = BoundOption<RenderSettings>;

// Every SETTING row, in the table's order.
const std::vector<SettingRow>& settingRows();
// The row of `field`; throws std::logic_error where there is none.
const SettingRow& settingRow(const std::string& field);

// The uniform a setting is given to the shader as ("uHitTolerance"), and the per-pixel copy
// of it that the shader's modules read ("gHitTolerance").
std::string uniformName(const std::string& field);
std::string perPixelCopyName(const std::string& field);

// "#define SAMPLER_SOBOL 1" lines: the code of every choice the shader sees (Choices.h).
std::string choiceDefines();

}  // namespace settings
