#include "settings/SettingsTable.h"

#include <cctype>
#include <stdexcept>

namespace settings {

const std::vector<SettingRow>& settingRows()
{
    static const std::vector<SettingRow> rows = {
#define SECTION(title)
#define OPTION(field, ...)
#define SETTING(Type, field, defaultValue, ...)                                                    \
    bindOption<RenderSettings>(                                                                    \
        #field, [](auto& s) -> auto& { return s.field; }, __VA_ARGS__),
#include "settings/Options.def"
#undef SECTION
#undef OPTION
#undef SETTING
    };
    return rows;
}

const SettingRow& settingRow(const std::string& field)
{
    for (const SettingRow& row : settingRows())
        if (row.field == field)
            return row;
    throw std::logic_error("no setting '" + field + "' in settings/Options.def");
}

namespace {

std::string capitalised(const std::string& name)
{
    std::string text = name;
    if (!text.empty())
        text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

}  // namespace

std::string uniformName(const std::string& field)
{
    return "u" + capitalised(field);
}

std::string perPixelCopyName(const std::string& field)
{
    return "g" + capitalised(field);
}

std::string choiceDefines()
{
    std::string text;
    for (const SettingRow& row : settingRows())
        text += row.choiceDefines;
    return text;
}

}  // namespace settings
