#pragma once
// Intel Open Image Denoise (OIDN), loaded at run time: never a build dependency. Debian does
// not package it; the pyoidn wheel bundles libOpenImageDenoise.so.2, and
// tools/install-dependencies.sh installs it in a virtual environment of its own. The library
// is looked for, in order, at
//   $RAYTRACER_OIDN_LIBRARY                     a path to libOpenImageDenoise.so.2
//   ~/.local/share/raytracer/oidn-venv          (or $RAYTRACER_OIDN_VENV) the wheel's copy
//   libOpenImageDenoise.so.2                    the dynamic loader's own search (a system install)
// and only the few C entry points used here are declared (OIDN 2's C API: device, filter,
// shared images, execute, error), so that no header is needed either.
#include "io/Image.h"

#include <stdexcept>
#include <string>

namespace film {

// OIDN could not be found or loaded; what() says where it was looked for and how to install it.
class DenoiserUnavailable : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

// Where the library was loaded from, loading it if it is not yet; throws DenoiserUnavailable.
std::string denoiserLibrary();

// Whether the library can be loaded (for tests to skip with the reason: denoiserLibrary()'s).
bool denoiserAvailable();

// The "RT" filter (ray-traced images) on linear HDR radiance, RGB, with the feature images
// as guides (OIDN asks for the first-hit albedo and normal; the normal only with the albedo):
// `albedo` and `normal` RGB, same size, or empty (width 0) for none. Runs on the CPU device
// (the images are in host memory). Throws DenoiserUnavailable without the library and
// std::runtime_error with OIDN's message when it fails.
io::Image denoiseImage(const io::Image& color, const io::Image& albedo, const io::Image& normal);

}  // namespace film
