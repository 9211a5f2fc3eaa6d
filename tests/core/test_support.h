#pragma once
// Paths and helpers shared by the core tests.

#include <filesystem>
#include <string>

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
inline std::filesystem::path resources(const std::string& relative = {})
{
    return std::filesystem::path(THESPIS_RESOURCES) / relative;
}

} // namespace thespis::test
