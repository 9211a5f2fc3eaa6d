#pragma once
// Paths and helpers shared by the core tests.

#include <filesystem>
#include <string>

// THESPIS_SANITIZED: set in AddressSanitizer builds, where the heaviest checks run with less
// work (g++ defines __SANITIZE_ADDRESS__, clang answers __has_feature).
#if defined(__SANITIZE_ADDRESS__)
#define THESPIS_SANITIZED 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define THESPIS_SANITIZED 1
#endif
#endif

namespace thespis::test {

/// ../shared/data: the real third-party data (motion capture, characters, probes).
inline std::filesystem::path sharedData(const std::string& relative = {})
{
    return std::filesystem::path(THESPIS_SHARED_DATA) / relative;
}
/// tests/data: fixtures and golden files the project made.
inline std::filesystem::path testData(const std::string& relative = {})
{
    return std::filesystem::path(THESPIS_TEST_DATA) / relative;
}
/// <build>/test-artifacts/NAME (the folder is made): pictures and files tests leave for people
/// to look at.
inline std::filesystem::path artifact(const std::string& name)
{
    const std::filesystem::path directory(THESPIS_TEST_ARTIFACTS);
    std::filesystem::create_directories(directory);
    return directory / name;
}
inline std::filesystem::path resources(const std::string& relative = {})
{
    return std::filesystem::path(THESPIS_RESOURCES) / relative;
}

} // namespace thespis::test
