#include "wearscale/io/checkpoint.hpp"

#include <chrono>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "wearscale/core/errors.hpp"
#include "wearscale/core/fft.hpp"
#include "wearscale/core/interrupt.hpp"
#include "wearscale/core/log.hpp"
#include "wearscale/core/sha256.hpp"
#include "wearscale/core/utc_time.hpp"
#include "wearscale/io/hdf5_file.hpp"

namespace wearscale {

namespace {
// Format 2: a SHA-256 checksum of the whole saved content, integer steps.
constexpr const char* kFormat = "wearscale checkpoint 2";
constexpr const char* kFormatPrefix = "wearscale checkpoint ";

// Names joined one a line (names never hold a newline: they are code's own).
std::string join_lines(const std::vector<std::string>& names) {
  std::string out;
  for (const auto& n : names) out += (out.empty() ? "" : "\n") + n;
  return out;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> out;
  std::size_t start = 0;
  while (start <= text.size() && !text.empty()) {
    const auto end = text.find('\n', start);
    out.push_back(text.substr(start, end == std::string::npos ? std::string::npos : end - start));
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return out;
}

std::string value_text(const nlohmann::json& j) { return j.is_string() ? j.get<std::string>() : j.dump(); }

// "key 'scale.macro.grid' was 64, is now 128" for the first difference of two
// resolved cases (JSON), or "" if they cannot be compared that way.
}  // namespace

std::filesystem::path resume_folder(const std::filesystem::path& resume, const std::filesystem::path& out) {
  std::error_code ec;
  if (!std::filesystem::is_directory(resume, ec))
    throw InputError(fmt::format("--resume {}: no such folder; give the output folder of the run to continue",
                                 resume.string()));
  if (!out.empty() && std::filesystem::weakly_canonical(out, ec) != std::filesystem::weakly_canonical(resume, ec))
    throw InputError(fmt::format("--out {} and --resume {} name different folders; a resumed run writes into the "
                                 "folder it continues",
                                 out.string(), resume.string()));
  return resume;
}

void require_fresh_start(const std::filesystem::path& checkpoint) {
  std::error_code ec;
  if (!std::filesystem::exists(checkpoint, ec)) return;
  const auto dir = checkpoint.parent_path().empty() ? std::filesystem::path(".") : checkpoint.parent_path();
  throw OutputError(fmt::format("{} holds the checkpoint of an unfinished run; continue it with --resume {}, or delete "
                                "{} to start afresh",
                                dir.string(), dir.string(), checkpoint.string()));
}

std::string case_fingerprint(const nlohmann::json& parameters) {
  nlohmann::json p = parameters;
  if (p.is_object())
    for (const char* key : {"run", "output", "sweep"}) p.erase(key);
  return p.dump();
}

std::string describe_case_difference(const std::string& was, const std::string& now) {
  try {
    const auto a = nlohmann::json::parse(was).flatten(), b = nlohmann::json::parse(now).flatten();
    auto key_of = [](const std::string& pointer) {
      std::string k = pointer.substr(1);
      for (auto& c : k)
        if (c == '/') c = '.';
      return k;
    };
    for (const auto& [k, v] : a.items()) {
      if (!b.contains(k)) return fmt::format("key '{}' was {}, is now absent", key_of(k), value_text(v));
      if (b[k] != v) return fmt::format("key '{}' was {}, is now {}", key_of(k), value_text(v), value_text(b[k]));
    }
    for (const auto& [k, v] : b.items())
      if (!a.contains(k)) return fmt::format("key '{}' was absent, is now {}", key_of(k), value_text(v));
  } catch (const nlohmann::json::exception&) {
  }
  return {};
}

namespace {
// Owners name HDF5 groups: "macro/bem-pin-on-disc" → "macro-bem-pin-on-disc".
std::string group_of(const std::string& owner) {
  std::string g = owner;
  for (auto& c : g)
    if (c == '/' || c == '.') c = '-';
  return "/owners/" + g;
}

}  // namespace

// ------------------------------------------------------------ checkpointer ---

Checkpointer::Checkpointer(std::filesystem::path file, std::string fingerprint, CheckpointPolicy policy)
    : file_(std::move(file)), fingerprint_(std::move(fingerprint)), policy_(policy),
      enabled_(policy.interval > 0.0 || policy.every_steps > 0) {}

Checkpointer Checkpointer::disabled() { return Checkpointer(); }

namespace {
// The checksum of a checkpoint's content: everything load() restores, each
// field length-prefixed, arrays by their bytes (bit for bit).
std::string checksum(const std::string& fingerprint, const std::string& wisdom,
                     const std::map<std::string, CheckpointState>& states) {
  Sha256 h;
  h.field(kFormat);
  h.field(fingerprint);
  h.field(wisdom);
  for (const auto& [owner, s] : states) {
    h.field(owner);
    h.field(std::to_string(s.step));
    for (const auto& [name, values] : s.arrays()) {
      h.field(name);
      h.field(std::string_view(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(double)));
    }
    for (const auto& [name, text] : s.texts()) {
      h.field(name);
      h.field(text);
    }
  }
  return h.hex();
}
}  // namespace

void Checkpointer::load() {  // InputError if missing, not HDF5, or damaged
  H5Reader::guarded(file_, [&](const H5Reader& file) { load(file); });
}

void Checkpointer::load(const H5Reader& h5) {
  const std::string name = h5.name();
  std::string format;
  try {
    format = h5.string_attribute("/", "format");
  } catch (const InputError&) {
  }
  if (format != kFormat) {
    if (format.rfind(kFormatPrefix, 0) == 0)
      throw InputError(fmt::format("{}: a checkpoint of format '{}', written by another version of wearscale (this one "
                                   "reads '{}'); resume with that version, or delete it to start afresh",
                                   name, format, kFormat));
    throw InputError(fmt::format("{}: not a wearscale checkpoint (format '{}', expected '{}')", name, format, kFormat));
  }
  const std::string was = h5.string_attribute("/", "fingerprint");
  const std::string wisdom = h5.string_attribute("/", "fftw_wisdom");
  std::map<std::string, CheckpointState> states;
  for (const auto& owner : split_lines(h5.string_attribute("/", "owners"))) {
    const std::string g = group_of(owner);
    CheckpointState s;
    s.origin = fmt::format("{} ({})", name, owner);
    const std::int64_t step = h5.integer_attribute(g, "step");
    if (step < 0) throw InputError(fmt::format("{}: attribute 'step' of '{}' is {}; allowed: ≥ 0", name, g, step));
    s.step = static_cast<long>(step);
    const auto arrays = split_lines(h5.string_attribute(g, "arrays"));
    for (std::size_t k = 0; k < arrays.size(); ++k) s.put(arrays[k], h5.read_exact(fmt::format("{}/a{}", g, k)));
    const auto texts = split_lines(h5.string_attribute(g, "texts"));
    for (std::size_t k = 0; k < texts.size(); ++k) s.put_text(texts[k], h5.string_attribute(g, fmt::format("t{}", k)));
    states[owner] = std::move(s);
  }
  if (h5.string_attribute("/", "sha256") != checksum(was, wisdom, states))
    throw InputError(fmt::format("{}: the checkpoint is damaged (its checksum does not match what it holds); delete it "
                                 "to start afresh",
                                 name));
  if (was != fingerprint_) {
    const std::string diff = describe_case_difference(was, fingerprint_);
    throw InputError(fmt::format("{}: the checkpoint belongs to a case with other parameters{}; resume with the case "
                                 "file and --set options of the interrupted run, or start afresh without --resume",
                                 name, diff.empty() ? "" : " (" + diff + ")"));
  }
  for (auto& [owner, s] : states) last_step_[owner] = s.step;
  states_ = std::move(states);
  if (!wisdom.empty() && !FFTPlanCache::global().import_wisdom_string(wisdom))
    log::warn("{}: its FFTW wisdom could not be imported; the resumed run may differ in the last digits", name);
  last_save_ = std::chrono::steady_clock::now();
}

const CheckpointState* Checkpointer::restored(const std::string& owner) const {
  const auto it = states_.find(owner);
  return it == states_.end() ? nullptr : &it->second;
}

void Checkpointer::at_step(const std::string& owner, long step, const std::function<CheckpointState()>& make) {
  const bool stop = interrupt_requested();
  bool due = stop;
  if (enabled_ && !due) {
    const long last = last_step_.count(owner) != 0 ? last_step_[owner] : 0;
    if (policy_.every_steps > 0 && step - last >= policy_.every_steps) due = true;
    if (policy_.interval > 0.0 &&
        std::chrono::duration<double>(std::chrono::steady_clock::now() - last_save_).count() >= policy_.interval)
      due = true;
  }
  if (due && enabled_) {
    CheckpointState s = make();
    s.step = step;
    save(owner, std::move(s));
  }
  if (stop) {
    if (enabled_) log::info("checkpoint saved at step {} in {}", step, file_.string());
    throw_if_interrupted(owner);
  }
}

void Checkpointer::save(const std::string& owner, CheckpointState state) {
  if (!enabled_) return;
  const auto start = std::chrono::steady_clock::now();
  last_step_[owner] = state.step;
  states_[owner] = std::move(state);
  write();
  last_save_ = std::chrono::steady_clock::now();
  ++saves_;
  seconds_saving_ += std::chrono::duration<double>(last_save_ - start).count();
}

void Checkpointer::write() const {
  // A temporary name until commit(), at once (outside the run's output set):
  // the previous checkpoint stays valid meanwhile.
  H5Writer h5(file_, Commit::Now);
  const std::string wisdom = FFTPlanCache::global().export_wisdom_string();
  h5.set_attribute("/", "format", kFormat);
  h5.set_attribute("/", "fingerprint", fingerprint_);
  h5.set_attribute("/", "wearscale_version", WEARSCALE_VERSION);
  h5.set_attribute("/", "written", utc_now());
  h5.set_attribute("/", "fftw_wisdom", wisdom);
  std::vector<std::string> owners;
  for (const auto& [owner, s] : states_) {
    owners.push_back(owner);
    const std::string g = group_of(owner);
    h5.set_attribute(g, "owner", owner);
    h5.set_integer_attribute(g, "step", s.step);
    std::vector<std::string> arrays, texts;
    for (const auto& [name, values] : s.arrays()) {
      h5.write_series(fmt::format("{}/a{}", g, arrays.size()), values);
      arrays.push_back(name);
    }
    for (const auto& [name, text] : s.texts()) {
      h5.set_attribute(g, fmt::format("t{}", texts.size()), text);
      texts.push_back(name);
    }
    h5.set_attribute(g, "arrays", join_lines(arrays));
    h5.set_attribute(g, "texts", join_lines(texts));
  }
  h5.set_attribute("/", "owners", join_lines(owners));
  h5.set_attribute("/", "sha256", checksum(fingerprint_, wisdom, states_));
  h5.commit();
}

void Checkpointer::discard() {
  if (file_.empty()) return;
  std::error_code ec;
  std::filesystem::remove(file_, ec);
}

}  // namespace wearscale
