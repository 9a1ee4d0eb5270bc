// The alignment model's binary snapshot, for the embedded model's on-disk cache.
#include "lm/alignment_model.hpp"

#include <cstring>
#include <string_view>

#include "lm/alignment_internal.hpp"
#include "lm/language_model.hpp"
#include "util/hash.hpp"

namespace clips::lm {

// ---- snapshot ------------------------------------------------------------------

namespace {

constexpr char kSnapshotMagic[8] = {'C', 'L', 'I', 'P', 'S', 'A', 'M', '4'};

// FNV-1a over the payload, stored last: a snapshot damaged on disk (a flipped
// bit in a probability) is rejected instead of scoring silently wrong.
uint64_t snapshot_checksum(std::string_view payload) { return util::fnv1a64(payload); }

struct Writer {
  std::string out;
  template <class T>
  void pod(const T& v) {
    out.append(reinterpret_cast<const char*>(&v), sizeof(T));
  }
  void size(size_t n) { pod(static_cast<uint64_t>(n)); }
  void str(const std::string& x) {
    size(x.size());
    out += x;
  }
  template <class T>
  void vec(const std::vector<T>& v) {
    size(v.size());
    if (!v.empty()) out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
  }
};

struct Reader {
  std::string_view in;  // the payload, without the trailing checksum
  size_t at = 0;
  void need(size_t n) const {
    if (n > in.size() - at) throw LmError("embedded LM snapshot: truncated at byte " + std::to_string(at));
  }
  template <class T>
  T pod() {
    need(sizeof(T));
    T v;
    std::memcpy(&v, in.data() + at, sizeof(T));
    at += sizeof(T);
    return v;
  }
  size_t size() {
    const uint64_t n = pod<uint64_t>();
    // No field is longer than the snapshot itself.
    if (n > in.size()) throw LmError("embedded LM snapshot: implausible length at byte " + std::to_string(at - 8));
    return static_cast<size_t>(n);
  }
  std::string str() {
    const size_t n = size();
    need(n);
    std::string x(in.substr(at, n));
    at += n;
    return x;
  }
  template <class T>
  std::vector<T> vec() {
    const size_t n = size();
    need(n * sizeof(T));
    std::vector<T> v(n);
    if (n != 0) std::memcpy(v.data(), in.data() + at, n * sizeof(T));
    at += n * sizeof(T);
    return v;
  }
};

}  // namespace

std::string AlignmentModel::save() const {
  Writer w;
  w.out.append(kSnapshotMagic, sizeof(kSnapshotMagic));
  w.size(words_.size());
  for (const std::string& x : words_) w.str(x);
  w.vec(word_flags_);
  w.vec(attribute_word_);
  w.pod(bag_kinds_);
  w.vec(char_first_);
  w.vec(char_next_);
  w.vec(bg_);
  w.pod(bg_unknown_scale_);
  w.pod(closed_mass_);
  w.size(tables_.size());
  for (const auto& t : tables_) {
    w.str(t->key);
    w.vec(t->prob);
    w.size(t->base.size());  // field by field: a pair has padding bytes
    for (const auto& [id, p] : t->base) {
      w.pod(id);
      w.pod(p);
    }
    w.pod(t->kappa);
  }
  w.pod(copy_alpha_);
  for (double m : mention_) w.pod(m);
  w.size(length_.size());
  for (const auto& row : length_) w.vec(row);
  w.vec(length_tail_scale_);
  w.vec(length_mean_);
  w.pod(snapshot_checksum(w.out));
  return std::move(w.out);
}

std::shared_ptr<AlignmentModel> AlignmentModel::load(const std::string& bytes) {
  if (bytes.size() < sizeof(kSnapshotMagic) + sizeof(uint64_t) ||
      std::memcmp(bytes.data(), kSnapshotMagic, sizeof(kSnapshotMagic)) != 0)
    throw LmError("embedded LM snapshot: not a snapshot of this format");
  const size_t payload = bytes.size() - sizeof(uint64_t);
  uint64_t stored = 0;
  std::memcpy(&stored, bytes.data() + payload, sizeof(stored));
  const std::string_view body(bytes.data(), payload);
  if (stored != snapshot_checksum(body)) throw LmError("embedded LM snapshot: checksum mismatch");
  Reader r{body, sizeof(kSnapshotMagic)};
  std::shared_ptr<AlignmentModel> m(new AlignmentModel());
  const size_t V = r.size();
  for (size_t i = 0; i < V; ++i) m->add_word(r.str());
  if (m->words_.size() != V) throw LmError("embedded LM snapshot: repeated vocabulary word");
  m->word_flags_ = r.vec<uint8_t>();
  m->attribute_word_ = r.vec<char>();
  m->bag_kinds_ = r.pod<uint8_t>();
  m->char_first_ = r.vec<double>();
  m->char_next_ = r.vec<double>();
  m->bg_ = r.vec<double>();
  m->bg_unknown_scale_ = r.pod<double>();
  m->closed_mass_ = r.pod<double>();
  const size_t nt = r.size();
  for (size_t i = 0; i < nt; ++i) {
    Table& t = *m->tables_[static_cast<size_t>(m->table_index(r.str()))];
    t.prob = r.vec<double>();
    const size_t nb = r.size();
    for (size_t j = 0; j < nb; ++j) {
      const int id = r.pod<int>();
      t.base.emplace_back(id, r.pod<double>());
    }
    t.kappa = r.pod<double>();
    if (t.prob.size() != V) throw LmError("embedded LM snapshot: table '" + t.key + "' does not cover the vocabulary");
    for (const auto& [id, p] : t.base)
      if (id < 0 || static_cast<size_t>(id) >= V) throw LmError("embedded LM snapshot: table '" + t.key + "' has a bad word id");
  }
  if (m->tables_.size() != nt) throw LmError("embedded LM snapshot: repeated table key");
  m->copy_alpha_ = r.pod<double>();
  for (double& x : m->mention_) x = r.pod<double>();
  const size_t nl = r.size();
  for (size_t i = 0; i < nl; ++i) m->length_.push_back(r.vec<double>());
  m->length_tail_scale_ = r.vec<double>();
  m->length_mean_ = r.vec<double>();
  const bool shapes_ok = m->word_flags_.size() == V && m->attribute_word_.size() == V && m->bg_.size() == V &&
                         m->char_first_.size() == static_cast<size_t>(kCharSymbols) &&
                         m->char_next_.size() == static_cast<size_t>(kCharSymbols * (kCharSymbols + 1)) &&
                         m->length_.size() == static_cast<size_t>(kMaxActionsBucket + 1) &&
                         m->length_tail_scale_.size() == m->length_.size() && m->length_mean_.size() == m->length_.size();
  if (!shapes_ok) throw LmError("embedded LM snapshot: arrays of the wrong shape");
  for (const auto& row : m->length_)
    if (row.size() != static_cast<size_t>(kMaxLen + 1)) throw LmError("embedded LM snapshot: arrays of the wrong shape");
  if (r.at != body.size()) throw LmError("embedded LM snapshot: trailing bytes");
  return m;
}

}  // namespace clips::lm
