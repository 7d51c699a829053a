#pragma once
// The kernel's names for messages and metadata: settings/Choices.h lists them with the
// enumeration (PathKernel), once.
#include "settings/Choices.h"

#include <optional>
#include <string>

namespace settings {

// "auto", "fragment", "compute" (for --kernel, messages and metadata).
inline const char* pathKernelName(PathKernel kernel)
{
    return Choices<PathKernel>::values[static_cast<std::size_t>(choiceCode(kernel))].name;
}

inline std::optional<PathKernel> pathKernelNamed(const std::string& name)
{
    for (const auto& choice : Choices<PathKernel>::values)
        if (name == choice.name)
            return choice.value;
    return std::nullopt;
}

}  // namespace settings
