#!/usr/bin/env python3
"""Man page and bash completion of one Orb tool, made from the tool's own --help.

The --help text is the one source: the C++ tools print it from their CLI11
option definitions (tools/common/src/help_formatter.cpp gives every option a
placeholder: FILE, DIR, N, X, global|direct, ...), orb-farm prints its own in
the same shape. An option added to a tool is therefore in its man page and its
completion at the next build, with nothing kept by hand here.

What the completion offers for a value follows from the help text alone:
  choices        a placeholder of lower-case words joined by '|' (global|direct),
                 or a description that lists them ("one of: scn, gltf, glb")
  files          placeholders FILE, OUT, PATTERN, PATH, SCENE, INPUT, ... and
                 positionals; filtered to the extensions the description names
                 ("(.scn, .gltf/.glb, ...)", "MAP.exr"), or to .exr where it
                 says EXR
  directories    DIR
  devices        --device of a tool that has --list-devices: "all", and each
                 device's index and platform, asked of the tool when completing
  nothing        numbers, lists and names (N, X, SECONDS, LIST, NAME, ...)

Usage: cli_reference.py --program PATH --name NAME --version V --date D
                        --see-also a,b,c [--man OUT.1.gz] [--bash OUT]
"""

from __future__ import annotations

import argparse
import dataclasses
import gzip
import re
import subprocess
import sys


@dataclasses.dataclass
class Item:
    """One name of an entry and the placeholder of its value ("" for a flag)."""

    name: str
    placeholder: str


@dataclasses.dataclass
class Entry:
    """One line of the option table: a positional or one or more options."""

    items: list[Item]
    description: str
    group: str
    positional: bool
    variadic: bool = False


@dataclasses.dataclass
class Help:
    name: str
    synopsis: str
    description: list[str]
    entries: list[Entry]
    examples: list[str]
    notes: list[str]


HEADER = re.compile(r"^([A-Za-z][A-Za-z0-9 ./-]*):$")
ENTRY = re.compile(r"^  (\S.*?)(?:\s{2,}(\S.*))?$")
OPTION_ITEM = re.compile(r"^(-{1,2}[A-Za-z0-9][A-Za-z0-9_-]*)(?:[ =](.+))?$")
POSITIONAL_ITEM = re.compile(r"^([A-Za-z][A-Za-z0-9_-]*)(\.\.\.)?$")


def parse_entry(line: str, group: str) -> Entry | None:
    match = ENTRY.match(line)
    if not match:
        return None
    names, description = match.group(1), match.group(2) or ""
    items = []
    for part in names.split(", "):
        option = OPTION_ITEM.match(part)
        if option:
            items.append(Item(option.group(1), (option.group(2) or "").strip()))
            continue
        positional = POSITIONAL_ITEM.match(part)
        if not positional or items:
            return None  # an example or prose, not an entry
        return Entry([Item(positional.group(1), "")], description, group, True, bool(positional.group(2)))
    # "-o, --output FILE": the short name takes the value the long one shows.
    for i in range(len(items) - 2, -1, -1):
        if not items[i].placeholder:
            items[i].placeholder = items[i + 1].placeholder
    return Entry(items, description, group, False)


def parse_help(name: str, text: str) -> Help:
    lines = text.splitlines()
    usage_at = next((i for i, line in enumerate(lines) if line.startswith("Usage:")), None)
    if usage_at is None:
        sys.exit(f"cli_reference: {name} --help has no 'Usage:' line")
    synopsis = lines[usage_at][len("Usage:"):].strip()
    if synopsis.startswith(name):
        synopsis = synopsis[len(name):].strip()
    description = [" ".join(line.strip() for line in lines[:usage_at] if line.strip())]
    description = [d for d in description if d]

    entries: list[Entry] = []
    examples: list[str] = []
    notes: list[str] = []
    paragraph: list[str] = []
    section = "Options"  # orb-farm lists its options under no header

    def end_paragraph():
        if paragraph:
            text = " ".join(paragraph)
            # orb-farm's description follows its usage line.
            if not description and not entries:
                description.append(text)
            else:
                notes.append(text)
            paragraph.clear()

    for line in lines[usage_at + 1:]:
        if not line.strip():
            end_paragraph()
            continue
        header = HEADER.match(line)
        if header:
            end_paragraph()
            section = header.group(1)
            continue
        if not line.startswith(" "):
            paragraph.append(line.strip())
            continue
        end_paragraph()
        if section == "Examples":
            # Past the examples' own indentation: a comment under its command, a command continued with "\\".
            examples.append(line[2:] if line.startswith("  ") else line.strip())
            continue
        if not line.startswith("   ") and (entry := parse_entry(line, section)):
            entries.append(entry)
            continue
        if entries:  # a description on the lines below its names
            last = entries[-1]
            last.description = (last.description + " " + line.strip()).strip()
            continue
        paragraph.append(line.strip())
    end_paragraph()

    variadic = {word[:-3] for word in synopsis.split() if word.endswith("...")}
    for entry in entries:
        if entry.positional and entry.items[0].name in variadic:
            entry.variadic = True
    return Help(name, synopsis, description, entries, examples, notes)


# ---------------------------------------------------------------- completion kinds

FILE_WORDS = {"FILE", "OUT", "OUTPUT", "PATTERN", "PATH", "SCENE", "INPUT", "INPUTS", "IMAGE", "MAP",
              "REFERENCE", "TEST"}
ONE_OF = re.compile(r"\bone of: ((?:[a-z0-9][a-z0-9_.-]*, )+[a-z0-9][a-z0-9_.-]*)")
EXTENSION_IN_TEXT = re.compile(r"(?:^|(?<=[\s(/,]))\.([a-z][a-z0-9]{1,4})\b")


def value_kind(cli: Help, name: str, placeholder: str, description: str) -> tuple:
    """How to complete the value of option `name` (or of a positional)."""
    if name == "--device" and any(i.name == "--list-devices" for e in cli.entries for i in e.items):
        return ("devices",)
    if re.fullmatch(r"N|X|[XYZ](,[XYZ])+", placeholder):
        return ("none",)  # a number or coordinates, whatever the description mentions
    alternatives = placeholder.split("|")
    if len(alternatives) > 1 and all(re.fullmatch(r"[a-z0-9][a-z0-9_.-]*", w) for w in alternatives):
        return ("words", alternatives)
    # Choices too many for a placeholder are listed in the description: "one of: scn, gltf, glb".
    listed = ONE_OF.search(description)
    if listed:
        return ("words", listed.group(1).split(", "))
    extensions = EXTENSION_IN_TEXT.findall(description)
    extensions += [m.group(1) for w in alternatives if (m := re.search(r"\w\.([a-z][a-z0-9]{1,4})$", w))]
    upper = placeholder.upper()
    if upper in ("DIR", "DIRECTORY", "FOLDER"):
        return ("dirs",)
    if extensions:
        return ("files", sorted(set(extensions), key=extensions.index))
    if upper in FILE_WORDS or upper.endswith("FILE") or "PATH" in upper:
        if re.search(r"\bEXRs?\b", description):
            return ("files", ["exr"])
        return ("files", [])
    return ("none",)


def bash_quote(word: str) -> str:
    return "'" + word.replace("'", "'\\''") + "'"


def bash_action(kind: tuple, function: str) -> str:
    if kind[0] == "devices":
        return f'COMPREPLY=($(compgen -W "$({function}_devices "${{words[0]}}")" -- "$cur"))'
    if kind[0] == "words":
        return f"COMPREPLY=($(compgen -W {bash_quote(' '.join(kind[1]))} -- \"$cur\"))"
    if kind[0] == "dirs":
        return "_filedir -d"
    if kind[0] == "files":
        return f"_filedir '@({'|'.join(kind[1])})'" if kind[1] else "_filedir"
    return ":"  # a number, a list or a name: nothing to offer


def bash_completion(cli: Help) -> str:
    function = "_" + re.sub(r"[^A-Za-z0-9]", "_", cli.name)
    options = [e for e in cli.entries if not e.positional]
    positionals = [e for e in cli.entries if e.positional]
    by_action: dict[str, list[str]] = {}
    valued: list[str] = []
    names: list[str] = []
    for entry in options:
        for item in entry.items:
            names.append(item.name)
            if item.placeholder:
                valued.append(item.name)
                action = bash_action(value_kind(cli, item.name, item.placeholder, entry.description), function)
                by_action.setdefault(action, []).append(item.name)

    out = [f"# bash completion for {cli.name}: generated from `{cli.name} --help` by",
           "# packaging/cli_reference.py when Orb was built; do not edit.", ""]
    if any(a.startswith("COMPREPLY=($(compgen -W \"$(") for a in by_action):
        out += [f"# The devices {cli.name} --device takes: all, and each device's index and",
                "# platform (its first word), from the tool's own --list-devices.",
                f"{function}_devices() {{",
                '    "$1" --list-devices 2>/dev/null | awk \'NR == 1 { at = index($0, "platform"); next }',
                '        $1 ~ /^[0-9]+$/ { print $1; if (at) { split(substr($0, at), w, " "); print tolower(w[1]) } }\'',
                "    echo all",
                "}", ""]
    out += [f"{function}() {{",
            "    local cur prev words cword split",
            "    _init_completion -s || return",
            "",
            '    case $prev in']
    for action, option_names in by_action.items():
        out.append(f"    {' | '.join(option_names)})")
        out.append(f"        {action}")
        out.append("        return ;;")
    out += ["    esac",
            "    $split && return",
            "",
            "    if [[ $cur == -* ]]; then",
            f"        COMPREPLY=($(compgen -W {bash_quote(' '.join(names))} -- \"$cur\"))",
            "        return",
            "    fi",
            "",
            "    # Which positional argument this is: options and their values do not count.",
            f"    local valued={bash_quote(' ' + ' '.join(valued) + ' ')} i positional=0",
            "    for ((i = 1; i < cword; i++)); do",
            "        [[ ${words[i]} == -- ]] && return  # the rest goes to another tool",
            "        if [[ ${words[i]} == -* ]]; then",
            '            [[ $valued == *" ${words[i]} "* ]] && ((i++))',
            "            continue",
            "        fi",
            "        ((positional++))",
            "    done"]
    if positionals:
        out.append("    case $positional in")
        for index, entry in enumerate(positionals):
            name = entry.items[0].name
            action = bash_action(value_kind(cli, name, name, entry.description), function)
            pattern = "*" if entry.variadic else str(index)  # a variadic one is the last
            out.append(f"    {pattern}) {action} ;;")
        out.append("    esac")
    out += ["}", f"complete -F {function} {cli.name}", ""]
    return "\n".join(out)


# ---------------------------------------------------------------- man page

def roff(text: str) -> str:
    text = text.replace("\\", "\\e").replace("-", "\\-")
    return "\n".join("\\&" + line if line.startswith((".", "'")) else line for line in text.split("\n"))


def first_clause(text: str) -> str:
    """The description up to its first '. ' or ': ' outside parentheses, for the NAME line."""
    depth = 0
    end = len(text)
    for i, c in enumerate(text):
        depth += {"(": 1, ")": -1}.get(c, 0)
        if depth == 0 and c in ".:" and (i + 1 == len(text) or text[i + 1] == " ") and text[i - 1:i].isalpha():
            end = i
            break
    clause = text[:end]
    return clause[:1].lower() + clause[1:] if clause[1:2].islower() else clause


def man_page(cli: Help, version: str, date: str, see_also: list[str]) -> str:
    title = cli.name.upper()
    out = [f".\\\" Generated from `{cli.name} --help` by packaging/cli_reference.py; do not edit.",
           f'.TH {roff(title)} 1 "{date}" "Orb {version}" "Orb manual"',
           ".SH NAME",
           f"{roff(cli.name)} \\- {roff(first_clause(cli.description[0] if cli.description else cli.name))}",
           ".SH SYNOPSIS",
           f".B {roff(cli.name)}",
           roff(cli.synopsis),
           ".SH DESCRIPTION"]
    for paragraph in cli.description:
        out += [".PP", roff(paragraph)]
    section = group = None
    for entry in sorted(cli.entries, key=lambda e: not e.positional):  # arguments first, else in order
        heading = "ARGUMENTS" if entry.positional else "OPTIONS"
        if heading != section:
            out.append(f".SH {heading}")
            section, group = heading, "Options"
        if not entry.positional and entry.group != group:
            out.append(f".SS {roff(entry.group)}")
            group = entry.group
        names = ", ".join(f"\\fB{roff(i.name)}\\fR" + (f" \\fI{roff(i.placeholder)}\\fR" if i.placeholder
                                                         and (i is entry.items[-1] or i.placeholder !=
                                                              entry.items[-1].placeholder) else "")
                          for i in entry.items)
        if entry.positional:
            names = f"\\fI{roff(entry.items[0].name)}\\fR" + ("..." if entry.variadic else "")
        out += [".TP", names, roff(entry.description) or "\\&"]
    if cli.examples:
        out += [".SH EXAMPLES", ".nf"]
        out += [roff(example) for example in cli.examples]
        out.append(".fi")
    exit_status = [n for n in cli.notes if n.startswith("Exit status:")]
    other_notes = [n for n in cli.notes if not n.startswith("Exit status:")]
    if other_notes:
        out.append(".SH NOTES")
        for note in other_notes:
            out += [".PP", roff(note)]
    if exit_status:
        out += [".SH EXIT STATUS", roff(exit_status[0][len("Exit status:"):].strip())]
    others = [p for p in see_also if p != cli.name]
    out += [".SH SEE ALSO", ",\n".join(f".BR {roff(p)} (1)" for p in others),
            ".PP",
            "Orb's documentation, in /usr/share/doc/orb/ when Orb is installed from its package:",
            "README.md and docs/*.md (each tool has a page, e.g.",
            f"docs/{roff(cli.name)}.md, where one exists)."]
    return "\n".join(out) + "\n"


def run(program: str, option: str) -> str:
    result = subprocess.run([program, option], capture_output=True, text=True, check=False)
    if result.returncode != 0:
        sys.exit(f"cli_reference: {program} {option} exited {result.returncode}: {result.stderr.strip()}")
    return result.stdout


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--program", required=True, help="the built tool to ask for --help")
    parser.add_argument("--name", required=True)
    parser.add_argument("--version", required=True)
    parser.add_argument("--date", required=True)
    parser.add_argument("--see-also", default="", help="the other tools, separated by ','")
    parser.add_argument("--man", help="write the gzipped man page here")
    parser.add_argument("--bash", help="write the bash completion here")
    args = parser.parse_args()

    cli = parse_help(args.name, run(args.program, "--help"))
    if not cli.entries:
        sys.exit(f"cli_reference: found no options in {args.name} --help")
    if args.man:
        page = man_page(cli, args.version, args.date, sorted(filter(None, args.see_also.split(","))))
        # mtime 0 and no file name: the same bytes at every build.
        with open(args.man, "wb") as out:
            out.write(gzip.compress(page.encode(), compresslevel=9, mtime=0))
    if args.bash:
        with open(args.bash, "w") as out:
            out.write(bash_completion(cli))


if __name__ == "__main__":
    main()
