// Files of the end-to-end tests: each test's own folder, and a file's bytes.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace monoplane {

// ctest runs the tests of a file in parallel processes: each test gets its own folder in the
// temporary directory, named after its suite and test.
inline std::filesystem::path test_folder() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return std::filesystem::temp_directory_path() /
           ("monoplane_e2e_" + std::string(info->test_suite_name()) + "_" + info->name());
}

// The file's bytes ("" for a file that cannot be read).
inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace monoplane
