// Writes the project's own environment maps into textures/ (they are committed; run this
// again after changing their definitions in EnvironmentMapImages.cpp):
//   build/tests/make_environment_maps
// sky-sun.hdr  a clear sky with a sun 35 degrees high, 256 x 128, Radiance RGBE: the
//              examples' outdoor light and the efficiency measurement's (docs/ACCURACY.md)
// octants.exr  one colour per octant of directions, 64 x 32, OpenEXR: shows the orientation
#include "io/ImageFile.h"
#include "support/EnvironmentMapImages.h"
#include "support/TestPaths.h"

#include <iostream>

int main()
{
    using namespace testing_support;
    const auto textures = sourceDirectory() / "textures";
    io::writeImage(textures / "sky-sun.hdr", skyWithSunEnvironmentMap(256, 128));
    io::writeImage(textures / "octants.exr", octantEnvironmentMap(64, 32));
    std::cout << "wrote " << (textures / "sky-sun.hdr").string() << " and "
              << (textures / "octants.exr").string() << "\n";
    return 0;
}
