#include "pddl/sexpr.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "util/utf8.hpp"

namespace clips::pddl {

const std::string& SExpr::head() const {
  static const std::string empty;
  if (!is_list || items.empty() || items[0].is_list) return empty;
  return items[0].atom;
}

std::string SExpr::str() const {
  if (!is_list) return atom;
  std::string s = "(";
  for (size_t i = 0; i < items.size(); ++i) {
    if (i) s += ' ';
    s += items[i].str();
  }
  return s + ")";
}

namespace {

class Reader {
 public:
  Reader(const std::string& text, const SourceLoc& origin)
      : t_(text), file_(origin.file), line_(origin.line), col_(origin.col) {
    if (t_.compare(0, 3, "\xEF\xBB\xBF") == 0) pos_ = 3;  // byte-order mark
  }

  // Reads every top-level expression; with `max_forms`, text after that many
  // is an error at once, before it is read (a PDDL file holds one form).
  std::vector<SExpr> all(size_t max_forms = std::string::npos) {
    std::vector<SExpr> out;
    for (;;) {
      skip();
      if (pos_ >= t_.size()) return out;
      if (out.size() == max_forms)
        throw SyntaxError(here(), "unexpected text after the end of the (define ...) expression");
      // A top-level atom cannot start a PDDL form: stop at the first one.
      if (max_forms != std::string::npos && t_[pos_] != '(' && t_[pos_] != ')')
        throw SyntaxError(here(), "expected '(' to open (define ...), found '" +
                                      printable(t_.substr(pos_, std::min<size_t>(20, t_.size() - pos_))) + "'");
      out.push_back(expr(1));
    }
  }

 private:
  SourceLoc here() const { return SourceLoc{file_, line_, col_}; }

  void advance() {
    if (t_[pos_] == '\n') {
      ++line_;
      col_ = 1;
    } else {
      ++col_;
    }
    ++pos_;
  }

  void skip() {
    while (pos_ < t_.size()) {
      char c = t_[pos_];
      if (c == ';') {
        while (pos_ < t_.size() && t_[pos_] != '\n') advance();
      } else if (std::isspace(static_cast<unsigned char>(c))) {
        advance();
      } else {
        return;
      }
    }
  }

  // `depth` is the nesting level of this expression (1 at the top).
  SExpr expr(int depth) {
    SExpr e;
    e.loc = here();
    // Every parsed node costs ~100 bytes: stop huge inputs before they cost gigabytes.
    if (++tokens_ > kMaxTokens)
      throw SyntaxError(e.loc, "more than " + std::to_string(kMaxTokens) +
                                   " tokens: input this large is not supported (real PDDL files have thousands)");
    char c = t_[pos_];
    if (c == ')') throw SyntaxError(e.loc, "unbalanced parentheses: unexpected ')'");
    if (c == '(') {
      if (depth > kMaxNesting)
        throw SyntaxError(e.loc, "nesting deeper than " + std::to_string(kMaxNesting) + " levels");
      e.is_list = true;
      advance();
      for (;;) {
        skip();
        if (pos_ >= t_.size())
          throw SyntaxError(e.loc, "unbalanced parentheses: '(' opened here is never closed");
        if (t_[pos_] == ')') {
          advance();
          return e;
        }
        e.items.push_back(expr(depth + 1));
      }
    }
    std::string sym;
    while (pos_ < t_.size()) {
      char d = t_[pos_];
      if (d == '(' || d == ')' || d == ';' || std::isspace(static_cast<unsigned char>(d))) break;
      // PDDL's grammar: '?' starts a variable, so "(at?x ?y)" is "at ?x ?y".
      if (d == '?' && !sym.empty()) break;
      sym += static_cast<char>(std::tolower(static_cast<unsigned char>(d)));
      advance();
    }
    // Names end up in JSON output and in the language model's prompts: a
    // byte that is not UTF-8 (a Latin-1 file) is an error here, where the
    // file and place are known.
    if (const size_t bad = util::invalid_utf8_at(sym); bad != std::string::npos) {
      std::string shown;
      for (unsigned char ch : sym) {
        static const char kHex[] = "0123456789abcdef";
        if (ch < 0x80 && ch >= 0x20) shown += static_cast<char>(ch);
        else shown += std::string("\\x") + kHex[ch >> 4] + kHex[ch & 15];
      }
      throw SyntaxError(e.loc, "name '" + printable(shown, 80) + "' is not valid UTF-8 (byte " +
                                   std::to_string(bad + 1) + " of the name); save the file as UTF-8");
    }
    e.atom = std::move(sym);
    return e;
  }

  const std::string& t_;
  std::string file_;
  size_t pos_ = 0;
  int line_ = 1;
  int col_ = 1;
  long tokens_ = 0;  // atoms and lists read so far
};

}  // namespace

std::vector<SExpr> read_sexprs(const std::string& text, const std::string& file) {
  return Reader(text, SourceLoc{file, 1, 1}).all();
}

std::vector<SExpr> read_pddl_forms(const std::string& text, const std::string& file) {
  return Reader(text, SourceLoc{file, 1, 1}).all(1);
}

SExpr read_one_sexpr(const std::string& text, const std::string& label) {
  return read_one_sexpr(text, SourceLoc{label, 1, 1});
}

SExpr read_one_sexpr(const std::string& text, const SourceLoc& origin) {
  auto all = Reader(text, origin).all();
  if (all.size() != 1)
    throw SyntaxError(all.size() > 1 ? all[1].loc : origin,
                      "expected exactly one expression, found " + std::to_string(all.size()));
  return std::move(all[0]);
}

std::string read_text_file(const std::string& path) {
  // An ifstream opens a directory and reads nothing, which would look like an empty file.
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw InputError(SourceLoc{path, 0, 0}, "is a directory, not a file");
  // A FIFO would block the open until a writer comes, and a device such as
  // /dev/zero never ends: only regular files are read.
  const auto st = std::filesystem::status(path, ec);
  if (!ec && std::filesystem::exists(st) && !std::filesystem::is_regular_file(st))
    throw InputError(SourceLoc{path, 0, 0}, "is not a regular file (a FIFO, device or socket); give a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(SourceLoc{path, 0, 0}, "cannot open file");
  // One copy of the text in memory, not two (a stream buffer and its string).
  if (std::filesystem::is_regular_file(path, ec)) {
    const auto size = std::filesystem::file_size(path, ec);
    if (!ec) {
      std::string text(static_cast<size_t>(size), '\0');
      in.read(text.data(), static_cast<std::streamsize>(size));
      text.resize(static_cast<size_t>(in.gcount()));
      return text;
    }
  }
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

std::string printable(const std::string& text, size_t max_len) {
  size_t n = std::min(text.size(), max_len);
  while (n < text.size() && n > 0 && (static_cast<unsigned char>(text[n]) & 0xC0) == 0x80)
    --n;  // do not split a UTF-8 character
  std::string out;
  for (size_t i = 0; i < n; ++i) {
    unsigned char c = static_cast<unsigned char>(text[i]);
    if ((c < 0x20 && c != '\t') || c == 0x7F) {
      static const char kHex[] = "0123456789abcdef";
      out += "\\x";
      out += kHex[c >> 4];
      out += kHex[c & 15];
    } else {
      out += static_cast<char>(c);
    }
  }
  if (n < text.size()) out += "...";
  return out;
}

}  // namespace clips::pddl
