#pragma once
// A GoogleTest fixture for picture tests: one offscreen renderer of Width × Height shared by the
// suite's tests, made once and closed before exit. Without an OpenGL context the tests fail:
// Mesa's software GL is one of the project's dependencies, so there always is one.

#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "render/offscreen_renderer.h"
#include "util/error.h"

namespace thespis::test {

template <int Width, int Height>
class OffscreenSuite : public ::testing::Test {
protected:
    static constexpr int kWidth = Width, kHeight = Height;
    static void SetUpTestSuite()
    {
        auto created = core::render::OffscreenRenderer::create(kWidth, kHeight);
        if (created)
            s_renderer = std::move(*created);
        else
            s_failure = core::describe(created.error());
    }
    static void TearDownTestSuite() { s_renderer.reset(); }
    void SetUp() override
    {
        if (!s_renderer)
            FAIL() << "No OpenGL context: " << s_failure;
    }
    static inline std::unique_ptr<core::render::OffscreenRenderer> s_renderer;
    static inline std::string s_failure;
};

} // namespace thespis::test
