"""docs/architecture.md stays short and true: its map names exactly the packages under rockly_desktop/,
and every file it links to (the decisions, the limits, the benchmark results) exists."""
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
ARCHITECTURE = ROOT / "docs" / "architecture.md"
PACKAGE_LINE = re.compile(r"^( {0,10})([a-z_0-9]+)/(\s|$)")


def map_packages(text: str) -> set:
    """The packages the map's folder tree names, as paths ("rockly_desktop/ui/run").

    The tree is the first fenced block under "## The map"; a package's line starts with its name and a
    slash, indented two spaces a level; the tree of rockly_desktop/ ends at the next unindented line.
    """
    section = text.split("## The map", 1)[1]
    block = section.split("```", 2)[1]
    named, stack = set(), []
    for line in block.splitlines():
        found = PACKAGE_LINE.match(line)
        if not found:
            continue
        depth = len(found.group(1)) // 2
        if depth == 0 and stack:
            break  # past rockly_desktop/: the repository's other folders
        stack[depth:] = [found.group(2)]
        named.add("/".join(stack))
    return named


def tree_packages() -> set:
    """Every package under rockly_desktop/ (a folder with an __init__.py), as paths."""
    return {str(init.parent.relative_to(ROOT)) for init in (ROOT / "rockly_desktop").rglob("__init__.py")}


def test_the_maps_packages_are_exactly_the_packages_under_rockly_desktop():
    named, real = map_packages(ARCHITECTURE.read_text(encoding="utf-8")), tree_packages()
    assert "rockly_desktop" in named
    assert not real - named, f"packages the map does not name: {sorted(real - named)}"
    assert not named - real, f"packages the map names that do not exist: {sorted(named - real)}"


def test_the_map_reader_sees_a_missing_and_an_invented_package():
    text = ARCHITECTURE.read_text(encoding="utf-8")
    assert "rockly_desktop/robot/ros2/helper" in map_packages(text)
    without_helper = re.sub(r"(?m)^      helper/.*$", "", text)
    assert "rockly_desktop/robot/ros2/helper" not in map_packages(without_helper)
    invented = text.replace("\n  core/", "\n  gadgets/     nothing\n  core/", 1)
    assert "rockly_desktop/gadgets" in map_packages(invented)


def test_the_architecture_doc_is_at_most_300_lines():
    assert len(ARCHITECTURE.read_text(encoding="utf-8").splitlines()) <= 300


def test_every_relative_link_in_the_architecture_doc_leads_to_a_file():
    text = ARCHITECTURE.read_text(encoding="utf-8")
    targets = [target for target in re.findall(r"\]\(([^)#]+)\)", text) if "://" not in target]
    assert targets
    missing = [target for target in targets if not (ARCHITECTURE.parent / target).exists()]
    assert not missing, f"links to nothing: {missing}"


def test_every_decision_file_is_linked_from_the_architecture_doc_and_numbered_in_order():
    text = ARCHITECTURE.read_text(encoding="utf-8")
    decisions = sorted(path.name for path in (ARCHITECTURE.parent / "decisions").glob("*.md"))
    assert decisions
    assert [name[:3] for name in decisions] == [f"{n:03d}" for n in range(1, len(decisions) + 1)]
    unlinked = [name for name in decisions if f"decisions/{name}" not in text]
    assert not unlinked, f"decisions the architecture doc does not link: {unlinked}"


def test_every_file_path_the_architecture_docs_name_exists():
    """A path in backticks (`ui/run_session.py`, `resources/blockly/templates.js`) in architecture.md,
    limits.md or a decision is a file, from the repository's root or from rockly_desktop/."""
    docs = [ARCHITECTURE, ARCHITECTURE.parent / "limits.md", *sorted((ARCHITECTURE.parent / "decisions").glob("*.md"))]
    missing = []
    for doc in docs:
        paths = set(re.findall(r"`([\w./-]+/[\w.-]+\.(?:py|js|yaml|md|txt))`", doc.read_text(encoding="utf-8")))
        missing += [f"{doc.name}: {path}" for path in sorted(paths)
                    if not (ROOT / path).is_file() and not (ROOT / "rockly_desktop" / path).is_file()]
    assert not missing, f"files the docs name that do not exist: {missing}"
