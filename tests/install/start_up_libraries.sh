#!/usr/bin/env bash
# The CLI starts without the libraries only some calls use (docs/decisions.md,
# "Optional libraries are opened when used"): libcurl, cairo, cpp-httplib and
# OpenSSL are not among its NEEDED entries; the HTTP module beside it needs
# cpp-httplib and none of the clips library.
#   tests/install/start_up_libraries.sh BUILD_DIR
set -euo pipefail
build="$1"
fail() { echo "start_up_libraries: $*" >&2; exit 1; }
needed() { readelf -d "$1" | sed -n 's/.*(NEEDED).*\[\(.*\)\]/\1/p'; }
[ -x "$build/clips" ] || fail "no $build/clips"
if needed "$build/clips" | grep -E 'libcurl|libcairo|httplib|libssl|libcrypto'; then
  fail "build/clips links the libraries above at start-up"
fi
module="$build/lib/clips-assist/clips-http.so"
[ -f "$module" ] || fail "no $module"
needed "$module" | grep -q httplib || fail "$module does not link cpp-httplib"
nm -D --defined-only "$module" | grep -q ' clips_http_serve$' || fail "$module does not export clips_http_serve"
if nm -D --defined-only "$module" | grep -q '_ZN5clips'; then fail "$module exports C++ symbols of clips"; fi
echo "start_up_libraries: ok ($(needed "$build/clips" | wc -l) libraries at start-up)"
