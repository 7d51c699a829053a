// main() of the executables whose tests draw with OpenGL. Every ctest test runs in its own
// process (gtest_discover_tests), and each process makes exactly one headless context,
// current on the main thread for all of its tests. The context is made when tests run, not
// when they are only listed, so listing needs no GL.
//
// --gl=KIND names the context: osmesa (the default) or egl (EGL on a GPU, else on Mesa's
// software device, else surfaceless: what a headless render takes first). ctest runs the
// render and regression tests through each (labels render-osmesa, render-egl, ...:
// tests/CMakeLists.txt).
#include "platform/ContextFactory.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>

namespace {

// From the arguments GoogleTest left (it removes its own).
platform::ContextKind contextKindFromArguments(int argc, char** argv)
{
    platform::ContextKind kind = platform::ContextKind::OsMesa;
    for (int i = 1; i < argc; ++i) {
        const std::string argument = argv[i];
        if (argument == "--gl=osmesa")
            kind = platform::ContextKind::OsMesa;
        else if (argument == "--gl=egl")
            kind = platform::ContextKind::Egl;
        else
            throw std::invalid_argument("unknown argument '" + argument +
                                        "' (this test program takes --gl=osmesa or --gl=egl)");
    }
    return kind;
}

class HeadlessContextEnvironment : public ::testing::Environment {
public:
    explicit HeadlessContextEnvironment(platform::ContextKind kind) : kind_(kind) {}

    void SetUp() override
    {
        platform::ContextRequest request;
        request.kind = kind_;
        context_ = platform::createContext(request);
        std::cout << "OpenGL: " << context_->description() << std::endl;
    }
    void TearDown() override { context_.reset(); }

private:
    platform::ContextKind kind_;
    std::unique_ptr<platform::GlContext> context_;
};

}  // namespace

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    try {
        ::testing::AddGlobalTestEnvironment(
            new HeadlessContextEnvironment(contextKindFromArguments(argc, argv)));
    } catch (const std::exception& error) {
        std::cerr << argv[0] << ": " << error.what() << "\n";
        return 2;
    }
    return RUN_ALL_TESTS();
}
