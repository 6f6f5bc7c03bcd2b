#pragma once
// A test process's own scratch folder under the system's temporary directory:
// the prefix followed by the process id; removed when the process ends with
// every test passed, kept for inspection when one failed.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <string>
#include <system_error>

class ScratchDir {
 public:
  explicit ScratchDir(const std::string& prefix)
      : path_(std::filesystem::temp_directory_path() / (prefix + std::to_string(::getpid()))) {
    // Constructed first, gtest's registry outlives this folder's destructor.
    ::testing::UnitTest::GetInstance();
  }
  ~ScratchDir() {
    const auto* suite = ::testing::UnitTest::GetInstance();
    if (suite->Failed()) return;
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  /// `name` inside the folder, which is created on first use.
  std::filesystem::path file(const std::string& name) const {
    std::filesystem::create_directories(path_);
    return path_ / name;
  }

 private:
  std::filesystem::path path_;
};
