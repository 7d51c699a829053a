// Writes every crafted render file (support/CraftedRenderFiles.h), made from BASE (a render
// the program wrote, at least 8x6), into FOLDER as NAME.exr: the EXR fuzz target's regression
// inputs, replayed by every build (tools/fuzz-render-files.sh --findings).
//   make_render_file_findings BASE.exr FOLDER
#include "support/CraftedRenderFiles.h"

#include <exception>
#include <filesystem>
#include <iostream>

int main(int argc, char* argv[])
{
    if (argc != 3) {
        std::cerr << "usage: make_render_file_findings BASE.exr FOLDER\n";
        return 2;
    }
    try {
        const std::filesystem::path folder = argv[2];
        std::filesystem::create_directories(folder);
        for (const auto& crafted : testing_support::craftedRenderFiles()) {
            const std::filesystem::path path = folder / (crafted.name + ".exr");
            testing_support::writeCraftedRenderFile(crafted, argv[1], path);
            std::cout << path.string() << "\n";
        }
    } catch (const std::exception& error) {
        std::cerr << "make_render_file_findings: " << error.what() << "\n";
        return 1;
    }
    return 0;
}
