#pragma once
// Where tests find data: the repo's own examples, and the paper's dataset
// ($CLIPS_DATASET or ../shared/dataset beside the checkout).
#include <cstdlib>
#include <filesystem>
#include <string>

namespace clips::paths {

inline std::string source_dir() { return CLIPS_SOURCE_DIR; }
inline std::string examples_dir() { return source_dir() + "/data/examples"; }
inline std::string shared_dataset_root() {
  if (const char* env = std::getenv("CLIPS_DATASET")) return env;
  return source_dir() + "/../shared/dataset";
}
inline std::string dkg_dataset() { return shared_dataset_root() + "/doors-keys-gems"; }
inline std::string vh_dataset() { return shared_dataset_root() + "/virtual-home"; }
inline bool have_shared_dataset() { return std::filesystem::exists(dkg_dataset() + "/domain.pddl"); }

}  // namespace clips::paths
