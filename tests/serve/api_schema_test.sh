#!/usr/bin/env bash
# CTest serve_api_schema: every request and reply the server tests send,
# checked against data/schema/serve-api.openapi.json (the OpenAPI 3.1
# document of every HTTP endpoint and --stdio message of `clips serve`).
# Runs the server tests (test_serve and test_serve_integration: the
# in-process handlers, the loopback HTTP server, the hardening and --stdio
# tests) and the robot example (examples/robot_loop.py against `clips serve
# --stdio`) with $CLIPS_SERVE_EXCHANGE_LOG set, so that the handlers log every
# exchange, then validates them (tests/serve/check_api_schema.py, Debian python3-jsonschema).
# Usage: api_schema_test.sh BUILD_DIR SOURCE_DIR
set -euo pipefail
build=$(realpath "$1")
src=$(realpath "$2")
fail() { echo "FAIL: $*" >&2; exit 1; }
/usr/bin/python3 -c "import jsonschema" 2>/dev/null || { echo "serve_api_schema: no python3-jsonschema; skipped"; exit 77; }
tmp=$(mktemp -d /tmp/clips-api-XXXXXX)
trap 'rm -rf "$tmp"' EXIT
export CLIPS_SERVE_EXCHANGE_LOG="$tmp/exchanges.jsonl" CLIPS_LM_CACHE_DIR="$build/lm-cache"

for t in test_serve test_serve_integration; do
  (cd "$src" && "$build/$t" --gtest_brief=1 >"$tmp/$t.log" 2>&1) || { tail -30 "$tmp/$t.log"; fail "$t failed"; }
done
/usr/bin/python3 "$src/examples/robot_loop.py" --clips "$build/clips" --dataset "$src/data/examples/doors-keys-gems" \
  >"$tmp/robot.log" 2>&1 || { cat "$tmp/robot.log"; fail "the robot example failed"; }
tail -1 "$tmp/robot.log"
[ -s "$CLIPS_SERVE_EXCHANGE_LOG" ] || fail "the server logged no exchange"
/usr/bin/python3 "$src/tests/serve/check_api_schema.py" "$src/data/schema/serve-api.openapi.json" "$CLIPS_SERVE_EXCHANGE_LOG"
