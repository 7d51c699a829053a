// main() of the executables whose tests draw with OpenGL. Every ctest test runs in its own
// process (gtest_discover_tests), and each process makes exactly one headless OSMesa context,
// current on the main thread for all of its tests. The context is made when tests run, not
// when they are only listed, so listing needs no GL.
#include "platform/OsMesaContext.h"

#include <gtest/gtest.h>

#include <memory>

namespace {

class OsMesaEnvironment : public ::testing::Environment {
public:
    void SetUp() override { context_ = std::make_unique<platform::OsMesaContext>(); }
    void TearDown() override { context_.reset(); }

private:
    std::unique_ptr<platform::OsMesaContext> context_;
};

}  // namespace

int main(int argc, char** argv)
{
    ::testing::InitGoogleTest(&argc, argv);
    ::testing::AddGlobalTestEnvironment(new OsMesaEnvironment);
    return RUN_ALL_TESTS();
}
