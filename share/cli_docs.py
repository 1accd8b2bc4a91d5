#!/usr/bin/env python3
"""Writes the man page's subcommand section and the bash completion from catplan's --help texts.

    cli_docs.py CATPLAN --man-include OUT.h2m --completion OUT.bash

Both are generated at build time from the command itself (CLI11's help format: sections
"Options:", "Positionals:", "Subcommands:", one option per line as "-o,--output TEXT  text",
choices as TEXT:{a,b}), so they cannot drift from it. help2man turns the include into the
SUBCOMMANDS section of catplan(1).
"""

import argparse
import re
import subprocess
import sys


def help_text(binary, path):
    r = subprocess.run([binary, *path, "--help"], capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"cli_docs.py: '{' '.join(['catplan', *path, '--help'])}' failed:\n{r.stderr}")
    return r.stdout


class Command:
    def __init__(self, path, text):
        self.path = path
        self.text = text
        self.subcommands = []  # names
        self.options = []  # [names, value type or "" for a flag, choices, description]
        section = None
        for line in text.splitlines():
            if line and not line.startswith(" ") and line.endswith(":"):
                section = line[:-1]
                continue
            if line.startswith("   ") and section == "Options" and self.options:
                self.options[-1][3] += " " + line.strip()  # a description on its own line
                continue
            if not line.startswith("  "):
                continue
            left, *desc = re.split(r"\s{2,}", line.strip())
            if section == "Subcommands":
                self.subcommands.append(left.split()[0])
            elif section == "Options":
                words = left.split()
                # A value's type is an upper-case word (TEXT, UINT, FLOAT), with choices as
                # TEXT:{a,b}; other words are annotations such as "Excludes: --all".
                kind = words[1] if len(words) > 1 and re.match(r"[A-Z]+\b", words[1]) else ""
                choices = re.findall(r"\{([^}]*)\}", kind)
                self.options.append([words[0].split(","), kind.split(":")[0],
                                     choices[0].split(",") if choices else [], " ".join(desc)])


def value_words(names, kind, choices, desc):
    """What completes an option's value: its choices, FILE, or NONE (a number, a name)."""
    if choices:
        return " ".join(choices)
    # Output files, and the plan file; the other TEXT values are declaration names.
    if kind == "TEXT" and ("this file" in desc or "--plan" in names):
        return "FILE"
    return "NONE"


def command_tree(binary):
    out, todo = [], [[]]
    while todo:
        path = todo.pop(0)
        c = Command(path, help_text(binary, path))
        out.append(c)
        todo += [path + [s] for s in c.subcommands]
    return out


def roff_text(text):
    lines = []
    for line in text.splitlines():
        line = line.replace("\\", "\\e").replace("-", "\\-")
        if line.startswith((".", "'")):
            line = "\\&" + line
        lines.append(line)
    return "\n".join(lines)


def man_include(commands):
    out = ["[SUBCOMMANDS]",
           "Each subcommand prints its own help with \\fB\\-\\-help\\fR, as follows."]
    for c in commands[1:]:
        if c.subcommands:
            continue  # a group: its leaves follow
        out += [f'.SS "catplan {" ".join(c.path)}"', ".nf", roff_text(c.text.rstrip()), ".fi"]
    out += ["[SEE ALSO]",
            "The language, the exit codes and the design are described in docs/language.md, "
            "docs/exit-codes.md and docs/architecture.md of catplan's sources."]
    return "\n".join(out) + "\n"


def completion(commands):
    names = {" ".join(c.path) for c in commands}
    steps = sorted(f'"{" ".join(c.path[:-1])}|{c.path[-1]}"' for c in commands if c.path)
    lines = [
        "# bash completion for catplan: subcommands, their options and the values of options",
        "# with a fixed set of values; files elsewhere. Generated from catplan's --help texts",
        "# by share/cli_docs.py: do not edit.",
        "_catplan_files() {",
        "    if declare -F _filedir >/dev/null; then _filedir; else",
        '        mapfile -t COMPREPLY < <(compgen -f -- "$cur"); fi',
        "}",
        "",
        "_catplan() {",
        '    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD-1]}',
        '    local path="" i subs="" opts="" values=""',
        "    for ((i = 1; i < COMP_CWORD; i++)); do",
        '        case "$path|${COMP_WORDS[i]}" in',
        f"            {'|'.join(steps)})",
        '                path="${path:+$path }${COMP_WORDS[i]}" ;;',
        "        esac",
        "    done",
        '    case "$path" in',
    ]
    for c in commands:
        opts = " ".join(n for o in c.options for n in o[0])
        lines.append(f'        "{" ".join(c.path)}") subs="{" ".join(c.subcommands)}"; '
                     f'opts="{opts}" ;;')
    lines += ["    esac", '    case "$path|$prev" in']
    for c in commands:
        for names_, kind, choices, desc in c.options:
            if not kind:
                continue
            values = value_words(names_, kind, choices, desc)
            pats = "|".join(f'"{" ".join(c.path)}|{n}"' for n in names_)
            lines.append(f'        {pats}) values="{values}" ;;')
    lines += [
        "    esac",
        '    if [[ $values == FILE ]]; then _catplan_files; return; fi',
        '    if [[ $values == NONE ]]; then COMPREPLY=(); return; fi',
        '    if [[ -n $values ]]; then',
        '        mapfile -t COMPREPLY < <(compgen -W "$values" -- "$cur"); return',
        "    fi",
        '    if [[ $cur == -* ]]; then',
        '        mapfile -t COMPREPLY < <(compgen -W "$opts" -- "$cur"); return',
        "    fi",
        '    if [[ -n $subs ]]; then',
        '        mapfile -t COMPREPLY < <(compgen -W "$subs" -- "$cur"); return',
        "    fi",
        "    _catplan_files",
        "}",
        "complete -F _catplan catplan",
    ]
    assert "" in names
    return "\n".join(lines) + "\n"


def main():
    p = argparse.ArgumentParser()
    p.add_argument("catplan")
    p.add_argument("--man-include", required=True)
    p.add_argument("--completion", required=True)
    a = p.parse_args()
    commands = command_tree(a.catplan)
    with open(a.man_include, "w", encoding="utf-8") as f:
        f.write(man_include(commands))
    with open(a.completion, "w", encoding="utf-8") as f:
        f.write(completion(commands))


if __name__ == "__main__":
    main()
