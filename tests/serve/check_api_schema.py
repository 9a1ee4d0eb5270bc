#!/usr/bin/env python3
"""Checks exchanges of `clips serve` against data/schema/serve-api.openapi.json.

Usage: check_api_schema.py SCHEMA LOG [LOG ...]

Each LOG holds the JSON lines $CLIPS_SERVE_EXCHANGE_LOG writes
(src/serve/exchange_log.hpp). For every exchange through the handlers:
  * its path and method name an operation of the document (else the reply
    must be a 404 or 405 Error);
  * its status is one the operation documents, or one any endpoint may answer;
  * its reply validates against that status's schema (JSON replies);
  * a request that succeeded (2xx) validates against the operation's request
    body schema, so the document does not refuse what the server takes.
Every --stdio line's request (when it parsed) and reply validate against
StdioRequest and StdioReply. At the end, every operation's success reply must
have been seen at least once, so the document has no endpoint the tests never
reach. Needs Debian's python3-jsonschema (Draft 2020-12). Exit 1 with the
first mismatches listed; 77 when jsonschema is missing.
"""
import collections
import json
import re
import sys

try:
    import jsonschema
except ImportError:
    print("check_api_schema: python3-jsonschema is not installed (scripts/install-deps.sh installs it)")
    sys.exit(77)

# Statuses any endpoint may answer (the connection rules of docs/api.md, and a bug).
ANY_STATUS = {"403", "408", "411", "414", "415", "431", "500"}


class Document:
    def __init__(self, path):
        with open(path, encoding="utf-8") as f:
            self.doc = json.load(f)
        for schema in self.doc["components"]["schemas"].values():
            jsonschema.Draft202012Validator.check_schema(schema)
        self.resolver = jsonschema.RefResolver.from_schema(self.doc)
        self.validators = {}
        self.routes = []  # (regex, template)
        for template in self.doc["paths"]:
            pattern = "^" + re.sub(r"\\\{[^}]+\\\}", "[^/]+", re.escape(template)) + "$"
            self.routes.append((re.compile(pattern), template))
        # Literal paths before templated ones ("/api/sessions" before "/api/sessions/{id}").
        self.routes.sort(key=lambda r: ("{" in r[1], -len(r[1])))

    def errors(self, schema, value):
        key = json.dumps(schema, sort_keys=True)
        if key not in self.validators:
            self.validators[key] = jsonschema.Draft202012Validator(schema, resolver=self.resolver)
        return sorted(self.validators[key].iter_errors(value), key=lambda e: list(e.path))

    def route(self, path):
        path = path.split("?", 1)[0]
        for regex, template in self.routes:
            if regex.match(path):
                return template
        return None

    def component(self, name):
        return {"$ref": f"#/components/schemas/{name}"}


def describe(errors):
    e = errors[0]
    where = "/".join(str(p) for p in e.absolute_path) or "(top)"
    return f"at {where}: {e.message[:300]}" + (f" (and {len(errors) - 1} more)" if len(errors) > 1 else "")


def response_schema(doc, operation, status):
    responses = operation["responses"]
    r = responses.get(status)
    if r is None and status in ANY_STATUS:
        r = {"$ref": "#/components/responses/Error"}
    if r is None:
        return None, False
    if "$ref" in r:
        r = doc.doc["components"]["responses"][r["$ref"].rsplit("/", 1)[1]]
    content = r.get("content", {})
    schema = (content.get("application/json") or next(iter(content.values()), {})).get("schema")
    return schema, True


def main():
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    doc = Document(sys.argv[1])
    problems = []
    seen = collections.Counter()
    counts = collections.Counter()
    for log in sys.argv[2:]:
        with open(log, encoding="utf-8") as f:
            for n, line in enumerate(f, 1):
                where = f"{log}:{n}"
                x = json.loads(line)
                if "stdio_reply" in x:
                    counts["stdio lines"] += 1
                    errs = doc.errors(doc.component("StdioReply"), x["stdio_reply"])
                    if errs:
                        problems.append(f"{where}: stdio reply: {describe(errs)}")
                    req, body = x["stdio_request"], x["stdio_reply"].get("body")
                    malformed = isinstance(body, dict) and str(body.get("error", "")).startswith("malformed request line")
                    if isinstance(req, dict) and not malformed:
                        errs = doc.errors(doc.component("StdioRequest"), req)
                        if errs:
                            problems.append(f"{where}: stdio request {json.dumps(req)[:120]}: {describe(errs)}")
                    continue
                counts["exchanges"] += 1
                method = "get" if x["method"] == "HEAD" else x["method"].lower()
                status = str(x["status"])
                reply = x["reply"]
                template = doc.route(x["path"])
                item = doc.doc["paths"].get(template, {}) if template else {}
                operation = item.get(method)
                if operation is None:
                    # Not an operation of the document: only "no such route" or "not this method".
                    if status not in ("404", "405"):
                        problems.append(f"{where}: {x['method']} {x['path'][:80]} answered {status}, "
                                        "but the document has no such operation")
                    errs = doc.errors(doc.component("Error"), reply)
                    if errs:
                        problems.append(f"{where}: error reply: {describe(errs)}")
                    continue
                schema, documented = response_schema(doc, operation, status)
                if not documented:
                    problems.append(f"{where}: {method.upper()} {template} answered {status}, which the document "
                                    f"does not list ({', '.join(operation['responses'])})")
                    continue
                if status.startswith("2"):
                    seen[(template, method)] += 1
                if x.get("content_type", "application/json") == "application/json" and schema is not None:
                    errs = doc.errors(schema, reply)
                    if errs:
                        problems.append(f"{where}: {method.upper()} {template} {status} reply: {describe(errs)}")
                if status.startswith("2") and "requestBody" in operation:
                    body = x["request"] if x["request"] is not None else {}
                    rschema = operation["requestBody"]["content"]["application/json"]["schema"]
                    errs = doc.errors(rschema, body)
                    if errs:
                        problems.append(f"{where}: {method.upper()} {template}: the server took a request the "
                                        f"document refuses, {json.dumps(body)[:160]}: {describe(errs)}")
    operations = [(t, m) for t, item in doc.doc["paths"].items() for m in item if m in ("get", "post", "delete")]
    unseen = [f"{m.upper()} {t}" for t, m in operations if not seen[(t, m)]]
    for t, m in operations:
        print(f"  {seen[(t, m)]:6d}  {m.upper():6s} {t}")
    print(f"check_api_schema: {counts['exchanges']} exchanges and {counts['stdio lines']} stdio lines checked")
    if unseen:
        problems.append("operations no test reached with a success: " + ", ".join(unseen))
    if problems:
        print(f"check_api_schema: {len(problems)} mismatches; the first ones:")
        for p in problems[:25]:
            print("  " + p)
        sys.exit(1)
    print("check_api_schema: OK")


if __name__ == "__main__":
    main()
