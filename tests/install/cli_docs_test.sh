#!/usr/bin/env bash
# CTest cli_docs: the manual page and the bash completion the Debian package
# installs, generated from the CLI's own --help by scripts/cli-docs.py (as
# the build does, build/share/clips-assist.*), without installing anything:
#   1. `man -l` renders the page with no groff warning, under the installed
#      name, with a section for every subcommand --help lists and the exit statuses;
#   2. the completion completes subcommands, nested ones (bench merge),
#      options and the values of options that take one of a list.
# Usage: cli_docs_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
fail() { echo "FAIL: $*" >&2; exit 1; }
tmp=$(mktemp -d /tmp/clips-docs-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
command -v man >/dev/null || { echo "cli_docs: no man (Debian man-db); skipped"; exit 77; }

python3 "$src/scripts/cli-docs.py" "$build/clips" clips-assist --man "$tmp/clips-assist.1.gz" \
  --bash-completion "$tmp/clips-assist" || fail "cli-docs.py failed"

# 1. The manual page.
page=$(MANWIDTH=100 man --warnings -E UTF-8 -l "$tmp/clips-assist.1.gz" 2>"$tmp/warnings") || fail "man -l failed"
[ ! -s "$tmp/warnings" ] || fail "groff warns: $(head -3 "$tmp/warnings")"
printf "%s\n" "$page" | sed -n 1,8p
grep -q "^NAME" <<<"$page" || fail "no NAME section"
grep -Eq "^ +clips-assist +- +infer +a +human" <<<"$page" || fail "the NAME line does not name clips-assist"
grep -q "^EXIT STATUS" <<<"$page" || fail "no EXIT STATUS section"
subcommands=$("$build/clips" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}')
[ -n "$subcommands" ] || fail "clips --help lists no subcommands"
for s in $subcommands; do
  grep -Eq "^ +clips-assist $s\$" <<<"$page" || fail "the page has no section for $s"
done
grep -q -- "--lm-prompt-logprobs" <<<"$page" || fail "the page lacks an option of --help"

# 2. The completion.
complete_words() {  # WORDS...: what completing the last word offers
  bash -c 'source "$1"; shift; COMP_WORDS=("$@"); COMP_CWORD=$(($# - 1)); _clips_assist; printf "%s\n" "${COMPREPLY[@]}"' \
    _ "$tmp/clips-assist" "$@" | sort | tr '\n' ' '
}
[ "$(complete_words clips-assist se)" = "serve " ] || fail "subcommands: $(complete_words clips-assist se)"
[ "$(complete_words clips-assist bench m)" = "merge " ] || fail "nested subcommands: $(complete_words clips-assist bench m)"
[ "$(complete_words clips-assist infer --lm-b)" = "--lm-base-url --lm-batch-size " ] \
  || fail "options: $(complete_words clips-assist infer --lm-b)"
[ "$(complete_words clips-assist infer --lm '')" = "embedded openai " ] || fail "values: $(complete_words clips-assist infer --lm '')"
[ "$(complete_words clips-assist bench merge --al)" = "--allow-partial " ] || fail "nested options"
echo "cli_docs: OK"
