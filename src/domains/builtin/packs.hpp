#pragma once
// The registration point of the compiled pack hooks: the table from a pack
// spec's "code" to its hooks (src/domains/dkg, src/domains/vh), and what
// needs it to make a Pack: finding a domain's pack, the built-in packs. The
// generic pack machinery (domains/pack.hpp) knows no code.
#include <memory>
#include <string>

#include "domains/pack.hpp"

namespace clips::domains {

// A pack from a spec: its "code" picks the compiled hooks ("" none).
PackPtr make_pack(PackSpec spec);
// Throws InputError ("code: ...") when the domain lacks what the compiled
// hooks of the spec's code read (the types, predicates and functions of the
// paper's domain they were written for).
void check_pack_code(const PackSpec& spec, const pddl::Domain& domain);
// The pack for a domain: its declared spec (declared_pack_spec: a folder's,
// the data folder's or the compiled-in pack.json), checked against the domain
// (check_pack_code, pack_spec_for_domain); else the generic pack.
PackPtr find_pack(const pddl::Domain& domain, const std::string& dir = "");
// A declared spec (a file's or a text's) made the pack of a domain: checked
// against it, with what clips adds and what it derives from the domain (goal
// atoms, location predicates). find_pack's last step.
PackPtr pack_for_domain(PackSpec spec, const pddl::Domain& domain);
// A domain file and its pack as clips grounds them: find_pack on the file's
// folder (or `dir`), and the domain with the pack's task transformations
// applied (task_transform.hpp), which problems are parsed against.
struct DomainWithPack {
  std::shared_ptr<const pddl::Domain> domain;
  PackPtr pack;
};
DomainWithPack load_domain_with_pack(const std::string& domain_file, const std::string& dir);
// The compiled-in pack of that name; InputError listing the known ones.
PackPtr builtin_pack(const std::string& name);

}  // namespace clips::domains
