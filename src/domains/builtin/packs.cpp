#include "domains/builtin/packs.hpp"

#include "domains/dkg/dkg_pack.hpp"
#include "domains/task_transform.hpp"
#include "domains/vh/vh_pack.hpp"
#include "pddl/parser.hpp"
#include "util/error.hpp"

namespace clips::domains {

namespace {

// Every compiled code: its name in pack.json, its pack, what it reads from a domain.
struct PackCode {
  const char* name;
  PackPtr (*make)(PackSpec);
  std::string (*misfit)(const pddl::Domain&);
};
constexpr PackCode kCodes[] = {
    {"doors-keys-gems", dkg::make_dkg_pack, dkg::dkg_misfit},
    {"virtual-home", vh::make_vh_pack, vh::vh_misfit},
};

const PackCode* find_code(const std::string& name) {
  for (const PackCode& c : kCodes)
    if (name == c.name) return &c;
  return nullptr;
}

}  // namespace

PackPtr make_pack(PackSpec spec) {
  if (spec.code.empty()) return std::make_shared<const Pack>(std::move(spec));
  if (const PackCode* c = find_code(spec.code)) return c->make(std::move(spec));
  std::string known;
  for (const PackCode& c : kCodes) known += (known.empty() ? "" : ", ") + std::string(c.name);
  throw InputError(SourceLoc{spec.source, 0, 0}, "code: no built-in pack code '" + spec.code + "' (known: " + known + ")");
}

void check_pack_code(const PackSpec& spec, const pddl::Domain& domain) {
  const PackCode* c = find_code(spec.code);
  if (!c) return;  // none, or unknown: make_pack names it
  if (const std::string misfit = c->misfit(domain); !misfit.empty())
    throw InputError(SourceLoc{spec.source.empty() ? "pack " + spec.name : spec.source, 0, 0},
                     "code: \"" + spec.code + "\" is the compiled code of the paper's " + spec.code +
                         " domain, and this domain does not have its shape (" + misfit + "): leave \"code\" out");
}

PackPtr find_pack(const pddl::Domain& domain, const std::string& dir) {
  if (auto spec = declared_pack_spec(domain, dir)) return pack_for_domain(std::move(*spec), domain);
  return make_pack(generic_pack_spec(domain));
}

PackPtr pack_for_domain(PackSpec spec, const pddl::Domain& domain) {
  check_pack_code(spec, domain);
  return make_pack(pack_spec_for_domain(std::move(spec), domain));
}

DomainWithPack load_domain_with_pack(const std::string& domain_file, const std::string& dir) {
  auto parsed = std::make_shared<const pddl::Domain>(pddl::load_domain(domain_file));
  DomainWithPack out;
  out.pack = find_pack(*parsed, dir);
  out.domain = prepare_domain(out.pack->spec(), std::move(parsed));
  return out;
}

PackPtr builtin_pack(const std::string& name) {
  auto spec = builtin_pack_spec(name);
  if (!spec) {
    std::string known;
    for (const auto& n : builtin_pack_names()) known += (known.empty() ? "" : ", ") + n;
    throw InputError("no built-in domain pack '" + name + "' (known: " + known + ")");
  }
  return make_pack(std::move(*spec));
}

}  // namespace clips::domains
