"""Toolboxes: a profile's own categories plus shared ones from ``toolboxes/`` by name.

A profile's ``toolbox.yaml``::

    categories:
      - name: {en: Drive, de: Fahren}
        colour: "#4C97FF"
        blocks:
          - my_robot_drive                    # a block by type
          - type: my_robot_turn               # or with Blockly toolbox JSON extras
            inputs: {angle: {shadow: {type: math_number, fields: {NUM: 90}}}}
      - shared: logic                         # toolboxes/logic.yaml

A shared category file has ``name``, ``colour`` and either ``blocks`` or ``custom``
(Blockly's dynamic VARIABLE / PROCEDURE categories); ``definitions: FILE`` names a block
file in ``toolboxes/`` whose blocks come with the category (the generic ROS blocks).
"""
from pathlib import Path

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.i18n import localize
from rockly_desktop.profiles.yaml_files import read_yaml_mapping


def _block_entry(item, path: Path, where: str) -> dict:
    if isinstance(item, str):
        return {"kind": "block", "type": item}
    if isinstance(item, dict) and isinstance(item.get("type"), str):
        return {"kind": "block", **item}
    raise ManifestError(path, where, "must be a block type, or a mapping with 'type'")


def _category(raw, path: Path, where: str) -> dict:
    if not isinstance(raw, dict) or "name" not in raw:
        raise ManifestError(path, where, "a category needs a 'name'")
    category = {"kind": "category", "name": raw["name"]}
    if "definitions" in raw:  # a shared category may bring its own block definitions
        category["definitions"] = str(raw["definitions"])
    if "colour" in raw:
        category["colour"] = str(raw["colour"])
    if "custom" in raw:
        category["custom"] = raw["custom"]
        return category
    blocks = raw.get("blocks")
    if not isinstance(blocks, list) or not blocks:
        raise ManifestError(path, f"{where}.blocks", "must list the blocks of the category")
    category["contents"] = [_block_entry(item, path, f"{where}.blocks[{index}]") for index, item in enumerate(blocks)]
    return category


def read_shared_category(name: str, folder: Path) -> dict:
    """Read ``toolboxes/NAME.yaml`` as a toolbox category."""
    path = folder / f"{name}.yaml"
    return _category(read_yaml_mapping(path), path, "category")


def shared_category_names(folder: Path) -> list:
    """Names of the shared categories available to every profile."""
    return sorted(path.stem for path in folder.glob("*.yaml"))


def read_toolbox(path: Path, shared_folder: Path, profile_block_types: set) -> list:
    """Read and validate a profile's toolbox; shared categories are resolved here."""
    data = read_yaml_mapping(path)
    raw_categories = data.get("categories")
    if not isinstance(raw_categories, list) or not raw_categories:
        raise ManifestError(path, "categories", "must be a non-empty list of categories")
    available = shared_category_names(shared_folder)
    categories = []
    for index, raw in enumerate(raw_categories):
        where = f"categories[{index}]"
        if isinstance(raw, dict) and "shared" in raw:
            if raw["shared"] not in available:
                raise ManifestError(path, f"{where}.shared",
                                    f"no shared category '{raw['shared']}' (there are: {', '.join(available)})")
            category = {**read_shared_category(raw["shared"], shared_folder), "shared": raw["shared"]}
        else:
            category = _category(raw, path, where)
            for position, entry in enumerate(category.get("contents", [])):
                if entry["type"] not in profile_block_types:
                    raise ManifestError(path, f"{where}.blocks[{position}]",
                                        f"block '{entry['type']}' is not defined in the profile's block file")
        categories.append(category)
    return categories


def shared_definition_files(categories: list, shared_folder: Path) -> list:
    """Block files that shared categories in ``categories`` bring along (``definitions:``)."""
    return [shared_folder / category["definitions"] for category in categories if "definitions" in category]


def category_names(category: dict) -> set:
    """The names a level may give a category by: its English name, and a shared category's file name."""
    name = category["name"]
    names = {name.get("en") if isinstance(name, dict) else name}
    if "shared" in category:
        names.add(category["shared"])
    return names


def toolbox_block_types(categories: list) -> set:
    """The block types the categories list."""
    return {entry["type"] for category in categories for entry in category.get("contents", [])}


def level_categories(categories: list, level: dict = None, hidden=frozenset()) -> list:
    """The categories a toolbox ``level`` keeps (None: all), without the ``hidden`` block types.

    A level keeps whole categories (``categories``: names, or ``all``) and single
    ``blocks`` from the others; a category left empty is dropped.
    """
    keep_all = level is None or level.get("categories") == "all"
    whole = set() if keep_all else set(level.get("categories", []))
    single = set(level.get("blocks", [])) if level else set()
    kept = []
    for category in categories:
        entire = keep_all or bool(category_names(category) & whole)
        if "contents" not in category:  # Blockly's dynamic categories (variables, functions)
            if entire:
                kept.append(category)
            continue
        contents = [entry for entry in category["contents"]
                    if (entire or entry["type"] in single) and entry["type"] not in hidden]
        if contents:
            kept.append({**category, "contents": contents})
    return kept


def toolbox_json(categories: list, language: str, catalogues=()) -> dict:
    """Blockly's category toolbox JSON with texts in ``language`` (see ``i18n.localize`` for ``catalogues``)."""
    contents = [{key: value for key, value in category.items() if key not in ("definitions", "shared")}
                for category in categories]
    return {"kind": "categoryToolbox", "contents": localize(contents, language, catalogues)}
