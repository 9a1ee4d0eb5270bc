#!/usr/bin/env python3
"""The manual page and the bash completion of the CLI, from its own --help.

Usage: cli-docs.py BINARY NAME --man OUT.1[.gz] --bash-completion OUT

Runs BINARY as NAME (argv[0], so the help says `clips-assist`, the installed
name) with --help and every subcommand's --help, and writes a man page
(section 1; gzipped, as Debian installs them, when OUT ends in .gz) and a
bash completion script: subcommands, each one's options, and the values of
options that take one of a list ({embedded,openai}). Standard library only.
"""
import argparse
import gzip
import re
import subprocess
import sys

OPTION_LINE = re.compile(r"^  (-\S.*?)(?:\s{2,}(\S.*))?$")
ENTRY_LINE = re.compile(r"^  (\S+)(?:\s{2,}(\S.*))?$")
CONTINUATION = re.compile(r"^ {20,}(\S.*)$")


def help_text(binary, name, words):
    r = subprocess.run([name, *words, "--help"], executable=binary, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"cli-docs: {name} {' '.join(words)} --help exited {r.returncode}: {r.stderr.strip()}")
    return r.stdout


def parse(text):
    """{'description': [...], 'usage': str, 'sections': {title: [(term, description)]}, 'footer': [...]}."""
    out = {"description": [], "usage": "", "sections": {}, "footer": []}
    section = None
    for line in text.splitlines():
        if line.startswith("Usage: "):
            out["usage"] = line[len("Usage: "):]
            section = ""
        elif section is None:
            if line.strip():
                out["description"].append(line.strip())
        elif re.match(r"^[A-Z][A-Za-z ]*:$", line):
            section = line[:-1]
            out["sections"].setdefault(section, [])
        elif line.startswith("Exit status"):
            section = "footer"
            out["footer"].append(line)
        elif section == "footer":
            out["footer"].append(line)
        elif section:
            entries = out["sections"][section]
            m = OPTION_LINE.match(line) or ENTRY_LINE.match(line)
            c = CONTINUATION.match(line)
            if c and entries:
                term, desc = entries[-1]
                entries[-1] = (term, (desc + " " + c.group(1)).strip())
            elif m:
                entries.append((m.group(1).strip(), (m.group(2) or "").strip()))
    return out


def collect(binary, name):
    """[(words, parsed help)] for the program and every (nested) subcommand, depth first."""
    found = []

    def visit(words):
        parsed = parse(help_text(binary, name, words))
        found.append((words, parsed))
        for sub, _ in parsed["sections"].get("Subcommands", []):
            visit(words + [sub])

    visit([])
    return found


def option_names(term):
    """'-j,--jobs INT:POSITIVE' -> ['-j', '--jobs']."""
    return [n for n in term.split()[0].split(",") if n.startswith("-")]


def option_choices(term):
    m = re.search(r"\{([^}]*)\}", term)
    return m.group(1).split(",") if m else []


def roff(text):
    text = text.replace("\\", "\\e")
    text = re.sub(r"(?<!\w)-", r"\\-", text)
    return text


def roff_line(text):
    text = roff(text)
    return "\\&" + text if text[:1] in (".", "'") else text


def term_roff(term):
    """Option names bold, the value's type in italics."""
    parts = term.split(None, 1)
    names = ", ".join(f"\\fB{roff(n)}\\fR" for n in parts[0].split(","))
    return names + (f" \\fI{roff(parts[1])}\\fR" if len(parts) > 1 else "")


def man_page(name, version_line, docs):
    top = docs[0][1]
    lines = [f'.TH {name.upper()} 1 "" "{roff(version_line)}" "User Commands"', ".SH NAME",
             f"{name} \\- {roff(top['description'][0].split(': ', 1)[-1].rstrip('.'))}", ".SH SYNOPSIS"]
    lines.append(f"\\fB{name}\\fR [\\fIOPTIONS\\fR] \\fISUBCOMMAND\\fR [\\fISUBCOMMAND OPTIONS\\fR]")
    lines += [".SH DESCRIPTION"] + [roff_line(d) for d in top["description"]]
    lines += [".PP", roff_line(f"Every subcommand takes --help; {name} --help-all prints them all. "
                               "The sections below are that help, one per subcommand.")]
    lines.append(".SH OPTIONS")
    for term, desc in top["sections"].get("Options", []):
        lines += [".TP", term_roff(term), roff_line(desc)]
    lines.append(".SH SUBCOMMANDS")
    for words, parsed in docs[1:]:
        lines.append(f'.SS "{name} {" ".join(words)}"')
        lines += [roff_line(d) for d in parsed["description"]]
        lines += [".PP", f"Usage: \\fB{roff(parsed['usage'])}\\fR"]
        for section in ("Positionals", "Options", "Subcommands"):
            entries = [(t, d) for t, d in parsed["sections"].get(section, []) if t not in ("-h,--help", "--help-all")]
            if not entries:
                continue
            lines += [".PP", f"\\fI{section}:\\fR"]
            for term, desc in entries:
                lines += [".TP", term_roff(term) if term.startswith("-") else f"\\fB{roff(term)}\\fR", roff_line(desc)]
    status = top["sections"].get("Exit status", [])
    if status:
        lines.append(".SH EXIT STATUS")
        for code, what in status:
            lines += [".TP", f"\\fB{code}\\fR", roff_line(what)]
    lines += [".SH ENVIRONMENT",
              roff_line("CLIPS_DATASET (the default dataset folder), CLIPS_DATA_DIR (the data folder), "
                        "CLIPS_LM_CACHE_DIR (the trained language model's cache; off turns it off), "
                        "CLIPS_LM_BASE_URL or OPENAI_BASE_URL, CLIPS_LM_MODEL, OPENAI_API_KEY and "
                        "CLIPS_LM_PROMPT_LOGPROBS (--lm openai), as the options above say."),
              ".SH FILES", roff_line(f"/usr/share/{name}: language corpora, domain packs, the JSON schemas "
                                     "(schema/serve-api.openapi.json: every request and reply of the serve "
                                     "subcommand) and an example dataset (examples/doors-keys-gems)."),
              ".SH SEE ALSO",
              roff_line(f"/usr/share/doc/{name}. Debian's clips(1) is another program: the CLIPS expert system.")]
    return "\n".join(lines) + "\n"


def completion(name, docs):
    func = "_" + re.sub(r"\W", "_", name)
    subs = {" ".join(w): p for w, p in docs}
    nested = {w[0]: [] for w, _ in docs if len(w) == 2}
    for w, _ in docs:
        if len(w) == 2:
            nested[w[0]].append(w[1])
    top_subs = " ".join(w[0] for w, _ in docs if len(w) == 1)
    out = [f"# bash completion for {name}; generated from its --help by scripts/cli-docs.py.",
           f"{func}() {{",
           '    local cur="${COMP_WORDS[COMP_CWORD]}" prev="${COMP_WORDS[COMP_CWORD-1]}" sub="" i w',
           "    for ((i = 1; i < COMP_CWORD; i++)); do",
           '        w="${COMP_WORDS[i]}"',
           '        case "$w" in -*) continue ;; esac',
           '        if [ -z "$sub" ]; then sub="$w"; continue; fi',
           '        case "$sub" in']
    for parent, children in nested.items():
        out.append(f'            {parent}) case "$w" in {"|".join(children)}) sub="$sub $w" ;; esac ;;')
    out += ["        esac", "    done", "    local opts=\"\"", '    case "$sub" in',
            f'        "") opts="{" ".join(n for t, _ in docs[0][1]["sections"].get("Options", []) for n in option_names(t))}" ;;']
    for key, parsed in subs.items():
        if not key:
            continue
        names = [n for t, _ in parsed["sections"].get("Options", []) for n in option_names(t)]
        out.append(f'        "{key}") opts="{" ".join(names)}" ;;')
    out.append("    esac")
    out.append('    case "$sub|$prev" in')
    for key, parsed in subs.items():
        for term, _ in parsed["sections"].get("Options", []):
            choices = option_choices(term)
            if choices:
                pattern = "|".join(f'"{key}|{n}"' for n in option_names(term))
                out.append(f'        {pattern}) COMPREPLY=($(compgen -W "{" ".join(choices)}" -- "$cur")); return ;;')
    out += ["    esac",
            '    if [[ "$cur" == -* ]]; then COMPREPLY=($(compgen -W "$opts" -- "$cur")); return; fi',
            f'    if [ -z "$sub" ]; then COMPREPLY=($(compgen -W "{top_subs}" -- "$cur")); return; fi',
            '    case "$sub" in']
    for parent, children in nested.items():
        out.append(f'        {parent}) COMPREPLY=($(compgen -W "{" ".join(children)}" -- "$cur")) ;;')
    out += ["    esac",
            "    COMPREPLY+=($(compgen -f -- \"$cur\"))",
            "}",
            f"complete -o filenames -F {func} {name}", ""]
    return "\n".join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("binary")
    ap.add_argument("name")
    ap.add_argument("--man", required=True)
    ap.add_argument("--bash-completion", required=True)
    args = ap.parse_args()
    docs = collect(args.binary, args.name)
    version = subprocess.run([args.name, "--version"], executable=args.binary, capture_output=True,
                             text=True).stdout.strip()
    page = man_page(args.name, version, docs).encode()
    if args.man.endswith(".gz"):
        with open(args.man, "wb") as f, gzip.GzipFile(filename="", mode="wb", fileobj=f, mtime=0,
                                                      compresslevel=9) as z:
            z.write(page)
    else:
        with open(args.man, "wb") as f:
            f.write(page)
    with open(args.bash_completion, "w", encoding="utf-8") as f:
        f.write(completion(args.name, docs))


if __name__ == "__main__":
    main()
