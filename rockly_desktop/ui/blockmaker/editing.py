"""Editing a made block again: what the maker's form shows for a saved ``MadeBlock``, which of its inputs the
open program fills (so a change that takes one away is said before it is saved), and the made blocks a
profile's packs hold (Tools → Edit a made block…)."""
import json
from dataclasses import dataclass
from pathlib import Path

from rockly_desktop.core.errors import ManifestError
from rockly_desktop.core.numbers import number_text
from rockly_desktop.profiles.packs.generate import block_definition
from rockly_desktop.profiles.packs.pack import load_pack, user_packs_dir

OFFER_KIND = {"publish": "topic", "sensor_value": "topic", "wait_until": "topic", "call_service": "service",
              "send_goal": "action", "get_param": "parameter", "set_param": "parameter"}
"""The kind of offer (``offers.KINDS_OF``'s keys) each block kind is made from."""


@dataclass(frozen=True)
class PackBeingEdited:
    """The pack of a made block shown again, as ``validation.block_problems`` checks an id against it: its id
    and its other blocks (the block keeps its own id)."""

    id: str
    block_types: frozenset

    @classmethod
    def of(cls, profile, pack_id: str, block_id: str) -> "PackBeingEdited":
        """``pack_id`` of ``profile``'s packs without ``block_id``."""
        types = next((pack.block_types for pack in getattr(profile, "packs", ()) if pack.id == pack_id), frozenset())
        return cls(pack_id, frozenset(types) - {block_id})


def value_text(value, kind: str, language: str) -> str:
    """``value`` as the field table shows it in ``language``, read back by ``field_table.read_value`` as the same
    value ("0,3" in German)."""
    if value is None:
        return ""
    if kind == "text" and isinstance(value, str):
        return value
    if kind == "number" and isinstance(value, (int, float)) and not isinstance(value, bool):
        return number_text(value, language)
    return json.dumps(value, ensure_ascii=False)  # JSON is YAML: lists, mappings, true, numbers


def made_block_ids(profile) -> list:
    """``[(pack id, block id)]`` of every block ``profile``'s packs made with the maker, by pack and id."""
    return sorted((pack.id, block_id) for pack in getattr(profile, "packs", ()) for block_id in pack.interfaces)


def saved_block(profile, block_id: str, folder=None):
    """``(pack id, MadeBlock)`` of the made block ``block_id`` as its pack's files (in ``folder``, None: the
    user's packs) say now, or None when no pack of ``profile``'s made it."""
    pack_id = next((pack for pack, made in made_block_ids(profile) if made == block_id), None)
    if pack_id is None:
        return None
    target = (Path(folder) if folder is not None else user_packs_dir()) / pack_id
    try:
        made = load_pack(target).made_block(block_id)
    except ManifestError:
        return None
    return (pack_id, made) if made is not None else None


def inputs_in_use(workspace: dict, block_type: str) -> set:
    """The names of the inputs of ``block_type``'s blocks that hold something in ``workspace`` (Blockly's
    JSON): a block plugged in, or a value typed into its own shadow."""
    used = set()

    def walk(node):
        if isinstance(node, dict):
            if node.get("type") == block_type:
                used.update(name for name, held in (node.get("inputs") or {}).items() if held)
            for value in node.values():
                walk(value)
        elif isinstance(node, list):
            for value in node:
                walk(value)

    walk(workspace)
    return used


def input_names(block) -> set:
    """The names of the inputs the made ``block`` has on the page (its values and a "while waiting" part)."""
    definition = block_definition(block)
    return {arg["name"] for key, args in definition.items() if key.startswith("args") for arg in args
            if str(arg.get("type", "")).startswith("input_")}


def keeping_only(block):
    """A function giving a workspace (Blockly JSON) whose blocks of ``block``'s type hold only what its inputs
    now take: Blockly refuses a whole program naming an input its block no longer has."""
    kept = input_names(block)

    def adapt(workspace: dict) -> dict:
        def walk(node):
            if isinstance(node, list):
                return [walk(value) for value in node]
            if not isinstance(node, dict):
                return node
            node = {key: walk(value) for key, value in node.items()}
            if node.get("type") == block.id and isinstance(node.get("inputs"), dict):
                node["inputs"] = {name: held for name, held in node["inputs"].items() if name in kept}
            return node
        return walk(workspace)
    return adapt


def choose_made_block(profile, language: str, parent) -> str:
    """Ask which made block of ``profile``'s to change (Tools → Edit a made block…): its id, "" for none
    (the person cancelled, or there is none yet, which is said)."""
    from PySide6.QtWidgets import QInputDialog, QMessageBox

    from rockly_desktop.ui.message_boxes import plain_message_box
    from rockly_desktop.ui.texts import tr

    ids = [block_id for _pack, block_id in made_block_ids(profile)]
    if not ids:
        plain_message_box(parent, QMessageBox.Icon.Information, tr("maker_edit_choose_title", language),
                          tr("maker_edit_none", language)).exec()
        return ""
    chosen, ok = QInputDialog.getItem(parent, tr("maker_edit_choose_title", language),
                                      tr("maker_edit_choose", language), ids, 0, False)
    return chosen if ok else ""
