#pragma once
// Two output folders of one case (a sweep run without mpirun and under
// mpirun, or merged from shards) hold the same outputs: the same files;
// every HDF5 dataset bit for bit (run.h5's time and command line aside, which
// are attributes); every JSON file equal and every other file byte for byte
// once the folder's own name is replaced by the other's (a summary's size of
// run.h5 aside: it holds the command line). Lock files, temporary
// files and the shards' manifests (task-K-of-N.json) are not outputs.
#include <gtest/gtest.h>

#include <hdf5.h>

#include <cstring>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "cli_runner.hpp"

namespace same_outputs {

namespace fs = std::filesystem;

inline bool is_output(const fs::path& relative) {
  for (const auto& part : relative)
    if (part.string().starts_with(".")) return false;
  const std::string name = relative.filename().string();
  return !(name.starts_with("task-") && name.find("-of-") != std::string::npos && name.ends_with(".json"));
}

inline std::set<std::string> files_of(const fs::path& dir) {
  std::set<std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file() && is_output(fs::relative(e.path(), dir))) out.insert(fs::relative(e.path(), dir).string());
  return out;
}

// Every dataset of an HDF5 file: its path → its raw bytes in the file's own type.
inline std::map<std::string, std::vector<unsigned char>> datasets_of(const fs::path& file) {
  std::map<std::string, std::vector<unsigned char>> out;
  const hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return out;
  H5Ovisit(
      f, H5_INDEX_NAME, H5_ITER_NATIVE,
      [](hid_t root, const char* name, const H5O_info_t* info, void* data) -> herr_t {
        if (info->type != H5O_TYPE_DATASET) return 0;
        const hid_t d = H5Dopen(root, name, H5P_DEFAULT);
        const hid_t type = H5Dget_type(d);
        const hid_t space = H5Dget_space(d);
        const auto points = static_cast<std::size_t>(H5Sget_simple_extent_npoints(space));
        std::vector<unsigned char> bytes;
        if (H5Tis_variable_str(type) > 0) {  // text: read as text
          std::vector<char*> text(points);
          H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data());
          for (char* t : text) bytes.insert(bytes.end(), t, t + std::strlen(t) + 1);
          H5Dvlen_reclaim(type, space, H5P_DEFAULT, text.data());
        } else {
          bytes.resize(points * H5Tget_size(type));
          H5Dread(d, type, H5S_ALL, H5S_ALL, H5P_DEFAULT, bytes.data());
        }
        (*static_cast<std::map<std::string, std::vector<unsigned char>>*>(data))[name] = std::move(bytes);
        H5Sclose(space);
        H5Tclose(type);
        H5Dclose(d);
        return 0;
      },
      &out);
  H5Fclose(f);
  return out;
}

inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  for (auto at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
    text.replace(at, from.size(), to);
  return text;
}

enum class Timings { Compared, Ignored };

inline bool is_timing(const std::string& dataset) {
  return dataset.starts_with("results/") && dataset.find("seconds") != std::string::npos;
}

/// `got` (a folder named differently) holds the outputs of `reference`.
inline void expect_same_outputs(const fs::path& reference, const fs::path& got, Timings timings = Timings::Compared) {
  const bool ignore_timings = timings == Timings::Ignored;
  const auto files = files_of(reference);
  ASSERT_FALSE(files.empty()) << reference;
  EXPECT_EQ(files, files_of(got)) << reference << " vs " << got;
  const std::string a = reference.filename().string(), b = got.filename().string();
  for (const auto& f : files) {
    if (!fs::exists(got / f)) continue;
    if (ignore_timings && (fs::path(f).filename() == "log.txt" || fs::path(f).extension() == ".log"))
      continue;  // a run's or a task's log: its times and ranks
    if (f.ends_with(".h5")) {
      const auto x = datasets_of(reference / f), y = datasets_of(got / f);
      EXPECT_FALSE(x.empty()) << f;
      EXPECT_EQ(x.size(), y.size()) << f;
      for (const auto& [name, bytes] : x) {
        ASSERT_TRUE(y.count(name)) << f << ": " << name;
        if (ignore_timings && is_timing(name)) continue;
        EXPECT_TRUE(bytes == y.at(name)) << f << ": dataset " << name << " differs";
      }
    } else if (f.ends_with(".json")) {
      // run.h5's size (in "outputs") depends on the length of its command line attribute.
      auto x = nlohmann::json::parse(slurp(reference / f)), y = nlohmann::json::parse(replaced(slurp(got / f), b, a));
      for (auto* j : {&x, &y})
        if (j->contains("outputs"))
          for (auto& [name, v] : (*j)["outputs"].items())
            if (name == "run.h5") v.erase("bytes");
      if (ignore_timings)
        for (auto* j : {&x, &y}) {
          if (!j->is_object()) continue;
          j->erase("tasks");
          if (j->contains("results") && (*j)["results"].is_object()) {
            std::vector<std::string> wall;
            for (const auto& [name, v] : (*j)["results"].items())
              if (name.find("seconds") != std::string::npos) wall.push_back(name);
            for (const auto& name : wall) (*j)["results"].erase(name);
          }
        }
      EXPECT_EQ(x, y) << f;
    } else {
      EXPECT_EQ(slurp(reference / f), replaced(slurp(got / f), b, a)) << f;
    }
  }
}

}  // namespace same_outputs
