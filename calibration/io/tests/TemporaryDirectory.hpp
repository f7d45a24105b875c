// Test helper: a fresh directory per test, removed afterwards.
#ifndef sdf_io_tests_TemporaryDirectory_hpp
#define sdf_io_tests_TemporaryDirectory_hpp

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <unistd.h>

namespace sdf::io::test
{

class TemporaryDirectory
{
public:
    TemporaryDirectory()
    {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        path_ = std::filesystem::temp_directory_path()
              / ("sdf_io_" + std::to_string(::getpid()) + "_" + info->test_suite_name() + "_" + info->name());
        std::filesystem::remove_all(path_);
        std::filesystem::create_directories(path_);
    }
    ~TemporaryDirectory()
    {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

    std::string file(const std::string& name) const { return (path_ / name).string(); }
    const std::filesystem::path& path() const { return path_; }

private:
    std::filesystem::path path_;
};

} // namespace sdf::io::test

#endif
