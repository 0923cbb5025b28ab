"""The documents against the tree: README.md's Layout block names exactly the
repository's top-level folders; docs/DESIGN.md's layer table lists the
library's layers in the Layout block's order, and each layer includes only
the layers its row allows; every file, folder and test that DESIGN.md cites
exists. No module or binary is needed."""

import pathlib
import re

ROOT = pathlib.Path(__file__).resolve().parents[2]
README = ROOT / "README.md"
DESIGN = ROOT / "docs" / "DESIGN.md"


def section(path, heading):
    """The text of the Markdown section `heading` (up to the next heading of
    the same or a higher level)."""
    text = path.read_text(encoding="utf-8")
    match = re.search(rf"^(#+) {re.escape(heading)}\s*$", text, re.MULTILINE)
    assert match, f"{path.name} has no section '{heading}'"
    level = len(match.group(1))
    end = re.compile(rf"^#{{1,{level}}} ", re.MULTILINE).search(text, match.end())
    return text[match.end():end.start() if end else len(text)]


def folders_in_code_block(text):
    """Folder names ("util/") at the start of the first code block's lines,
    in order; a line may name several ("cli/ python/ tests/")."""
    block = re.search(r"^```[^\n]*\n(.*?)^```", text, re.MULTILINE | re.DOTALL)
    assert block, "no code block"
    names = []
    for line in block.group(1).splitlines():
        for token in line.split():
            if not re.fullmatch(r"[A-Za-z0-9_.-]+/", token):
                break  # the description starts
            names.append(token[:-1])
    return names


def top_level_folders():
    return {p.name for p in ROOT.iterdir()
            if p.is_dir() and not p.name.startswith((".", "build")) and p.name != "__pycache__"}


def readme_layout():
    return folders_in_code_block(section(README, "Layout"))


def test_readme_layout_names_every_top_level_folder_once():
    named = readme_layout()
    assert len(named) == len(set(named)), f"named twice: {sorted({n for n in named if named.count(n) > 1})}"
    missing = sorted(top_level_folders() - set(named))
    stale = sorted(set(named) - top_level_folders())
    assert not missing and not stale, (
        f"README.md's Layout block and the tree differ: folders not in the block {missing}, "
        f"named in the block but not in the tree {stale}")


def design_layer_table():
    """DESIGN.md §1's table as (layer, the layers it may use), in order. The
    last column is "—", "every layer above" or a list such as "util, sites"."""
    rows = re.findall(r"^\|\s*`([a-z_]+)/`\s*\|[^|]*\|([^|]*)\|\s*$", section(DESIGN, "1. Layers"), re.MULTILINE)
    assert rows, "DESIGN.md §1 has no layer table"
    table = []
    for layer, uses in rows:
        uses = uses.strip()
        if uses == "every layer above":
            allowed = [name for name, _ in table]
        elif uses in ("—", "-", ""):
            allowed = []
        else:
            allowed = [name.strip() for name in uses.split(",")]
        table.append((layer, allowed))
    return table


def design_layers():
    return [layer for layer, _ in design_layer_table()]


def test_design_layer_table_follows_the_readme_layout():
    layers = design_layers()
    layout = readme_layout()
    assert set(layers) <= set(layout), f"layers missing from README's Layout: {sorted(set(layers) - set(layout))}"
    in_readme_order = [name for name in layout if name in layers]
    assert layers == in_readme_order, "DESIGN.md §1 lists the layers in another order than README's Layout"


INCLUDE = re.compile(r'^\s*#\s*include\s+"([a-z_]+)/', re.MULTILINE)


def test_layers_include_only_the_layers_design_allows():
    """Each layer's files include only their own layer and those its row of
    DESIGN.md §1 lists (layers not in the tree yet are skipped)."""
    table = design_layer_table()
    layers = {layer for layer, _ in table}
    wrong = []
    for layer, allowed in table:
        for unknown in set(allowed) - layers:
            wrong.append(f"{layer}/: its row names {unknown}/, which is no layer")
        folder = ROOT / layer
        if not folder.is_dir():
            continue
        for source in sorted(folder.rglob("*")):
            if source.suffix not in (".hpp", ".cpp", ".h"):
                continue
            for used in INCLUDE.findall(source.read_text(encoding="utf-8", errors="replace")):
                if used != layer and used not in allowed:
                    wrong.append(f"{source.relative_to(ROOT)} includes {used}/")
    assert not wrong, "includes against the layer table of docs/DESIGN.md §1:\n" + "\n".join(sorted(set(wrong)))


# `folder/name.ext`, `folder/name.*`, `folder/name.{hpp,cpp}`, `folder/`.
CITED_PATH = re.compile(r"`([a-z_]+/[A-Za-z0-9_./*{},-]*)`")
# Tests are cited by file name: they may live in any folder of tests/.
CITED_TEST = re.compile(r"`?\b(test_[a-z0-9_]+\.(?:cpp|py))\b")


def expansions(cited):
    braces = re.fullmatch(r"(.*)\{([^}]*)\}(.*)", cited)
    if braces:
        return [braces.group(1) + alternative + braces.group(3) for alternative in braces.group(2).split(",")]
    return [cited]


def exists(pattern):
    return any(ROOT.glob(pattern.rstrip("/"))) if "*" in pattern else (ROOT / pattern).exists()


def test_design_citations_exist():
    text = DESIGN.read_text(encoding="utf-8")
    missing = sorted({cited for cited in CITED_PATH.findall(text)
                      if not all(exists(p) for p in expansions(cited))})
    tests = {p.name for p in (ROOT / "tests").rglob("test_*") if p.is_file()}
    missing += sorted(set(CITED_TEST.findall(text)) - tests)
    assert not missing, f"docs/DESIGN.md cites what the tree does not hold: {missing}"


def test_the_layout_parser_reads_what_it_should():
    text = "intro\n```\nutil/   RAII types\n        over FLINT\ncli/ python/ tests/\n```\n"
    assert folders_in_code_block(text) == ["util", "cli", "python", "tests"]
    assert expansions("predicates/incircle.{hpp,cpp}") == ["predicates/incircle.hpp", "predicates/incircle.cpp"]
