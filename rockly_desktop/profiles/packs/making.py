"""Writing a made block into a block pack: all of it or nothing.

``save_block`` checks the block, then writes the whole pack anew into a hidden folder beside
it, reads that back as a pack and merges it into the profile (so a pack that would not load
is never installed), and only then puts it in place of the old folder. A failure at any step
leaves the old pack as it was. The definitions of the types the block uses that Rockly knows only
because the robot said them go into the pack's ``messages`` folder with it, so the pack works after a
restart and on another computer, with nothing publishing them.
"""
import os
import re
import shutil
import tempfile
from dataclasses import replace
from pathlib import Path

import yaml

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.core.errors import ManifestError
from rockly_desktop.profiles.packs.generate import block_definition, texts_in_languages, toolbox_entry
from rockly_desktop.profiles.packs.merge import with_pack
from rockly_desktop.profiles.packs.pack import (
    MADE_FILE,
    PACK_MANIFEST,
    is_pack_folder,
    load_pack,
    user_packs_dir,
)
from rockly_desktop.profiles.packs.spec import INTERFACE_KINDS
from rockly_desktop.profiles.packs.validation import IDENTIFIER, BlockMakerError, check_block
from rockly_desktop.profiles.yaml_files import read_yaml_mapping

FIRST_VERSION = "1.0.0"
MESSAGES_FOLDER = "messages"
_PATCH = re.compile(r"^(\d+)\.(\d+)\.(\d+)$")


class _PackDumper(yaml.SafeDumper):
    """YAML's own dumper, but a text holding one of YAML's extra line breaks (NEL, LS, PS) is written in
    double quotes, where they are escaped: in single quotes PyYAML writes NEL raw and reads it back as a space."""


def _text(dumper, text: str):
    style = '"' if any(mark in text for mark in "\x85\u2028\u2029") else None
    return dumper.represent_scalar("tag:yaml.org,2002:str", text, style=style)


_PackDumper.add_representer(str, _text)


def dump_yaml(data) -> str:
    """``data`` as YAML a person can read and edit (keys in the order given, texts as they are)."""
    return yaml.dump(data, Dumper=_PackDumper, allow_unicode=True, sort_keys=False, width=120,
                     default_flow_style=False)


def next_version(version: str) -> str:
    """The version after ``version``: its last number one higher (``1.0.3`` → ``1.0.4``); others unchanged."""
    match = _PATCH.fullmatch(str(version))
    return f"{match[1]}.{match[2]}.{int(match[3]) + 1}" if match else str(version)


def new_manifest(pack_id: str, profile, name=None) -> dict:
    """The ``pack.yaml`` of a new pack ``pack_id`` adding to ``profile``."""
    return {"schema": 1, "id": pack_id, "name": texts_in_languages(name) or pack_id, "version": FIRST_VERSION,
            "adds_to": profile.id, "languages": ["en", "de"], "blocks": "blocks.yaml", "toolbox": "toolbox.yaml"}


def _base_profile(profile, pack_id):
    """``profile`` without the blocks of the pack ``pack_id`` (it is merged again as the new pack); the
    types of the pack's definitions stay known, as the new pack keeps them."""
    if pack_id not in {pack.id for pack in getattr(profile, "packs", ())}:
        return profile
    types = next(pack.block_types for pack in profile.packs if pack.id == pack_id)
    categories = [{**category, "contents": [entry for entry in category["contents"] if entry["type"] not in types]}
                  if "contents" in category else category for category in profile.toolbox_categories]
    return replace(profile, blocks=tuple(spec for spec in profile.blocks if spec.type not in types),
                   toolbox_categories=[category for category in categories if category.get("contents", True)],
                   packs=tuple(replace(pack, block_types=frozenset(), interfaces={}) if pack.id == pack_id else pack
                               for pack in profile.packs))


def _category_name(category) -> str:
    return category.get("en") if isinstance(category, dict) else category


def _added_to_toolbox(categories: list, block) -> list:
    name = texts_in_languages(block.category)
    entry = toolbox_entry(block)
    for category in categories:
        if _category_name(category.get("name")) == name["en"]:
            category["blocks"] = [*category.get("blocks", []), entry]
            return categories
    return [*categories, {"name": name if len(name) > 1 else name["en"], "colour": block.colour, "blocks": [entry]}]


def _without(raw: dict, key: str, block_id: str) -> list:
    """The entries of ``raw[key]`` (blocks.yaml's by ``type``, made.yaml's by ``id``) but ``block_id``'s."""
    return [item for item in raw.get(key, []) if not (isinstance(item, dict) and item.get("type", item.get("id"))
                                                      == block_id)]


def save_block(block, profile, pack_id: str, *, folder=None, pack_name=None, version=None,
               replace_block=False):
    """Write the made ``block`` into the pack ``pack_id`` (made if new) adding to ``profile``
    (the profile as the registry merged it, so ids of every installed pack are checked).

    ``replace_block`` replaces a block of the same id in that pack (the maker's "save changes").
    The pack's version goes one up (``version`` sets it instead). Returns the written Pack;
    raises BlockMakerError (nothing written) when the block or the resulting pack is wrong.
    """
    if not isinstance(pack_id, str) or not IDENTIFIER.fullmatch(pack_id):
        raise BlockMakerError(app_local_text("pack_id_bad", id=pack_id))
    folder = Path(folder) if folder is not None else user_packs_dir()
    target = folder / pack_id
    existing = load_pack(target) if is_pack_folder(target) else None
    if existing is not None and existing.adds_to != profile.id:
        raise BlockMakerError(app_local_text("pack_adds_to_other", pack=pack_id, other=existing.adds_to,
                                             profile=profile.id))
    base = _base_profile(profile, pack_id)
    if existing is not None and replace_block:
        existing = replace(existing, blocks=tuple(spec for spec in existing.blocks if spec.type != block.id))
    check_block(block, base, existing)
    files = _pack_files(block, profile, existing, pack_id, pack_name, version)
    learnt = learnt_definition_files(block, base, existing.message_folder if existing is not None else None)
    if learnt:
        manifest = files[PACK_MANIFEST]
        manifest.setdefault("messages", MESSAGES_FOLDER)
        files.update({f"{manifest['messages']}/{name}": text for name, text in learnt.items()})
    return _write_pack(target, files, base, existing)


def learnt_definition_files(block, profile, into=None) -> dict:
    """``{"package/kind/Name.kind": text}`` of the type ``block`` uses and the types nested in it that ``profile``
    knows only because the robot said them, for the definitions folder ``into`` (the pack's, None for a new pack;
    see ``DefinitionCatalog.learnt_files``)."""
    kind = INTERFACE_KINDS.get(block.kind)
    return profile.ros_types.learnt_files(block.interface_type, kind, into) if kind and block.interface_type else {}


def _pack_files(block, profile, existing, pack_id, pack_name, version) -> dict:
    """The YAML texts of the pack with ``block`` added: {file name: data}."""
    if existing is None:
        manifest = new_manifest(pack_id, profile, pack_name)
        blocks, categories, made = [], [], []
    else:
        manifest = dict(existing.manifest)
        manifest["version"] = next_version(manifest["version"])
        if pack_name:
            manifest["name"] = texts_in_languages(pack_name)
        root = existing.root
        blocks = _without(read_yaml_mapping(root / manifest["blocks"]), "blocks", block.id)
        categories = []
        for category in read_yaml_mapping(root / manifest["toolbox"]).get("categories", []):
            kept = [entry for entry in category.get("blocks", [])
                    if (entry if isinstance(entry, str) else entry.get("type")) != block.id]
            if kept:
                categories.append({**category, "blocks": kept})
        made_path = root / MADE_FILE
        made = _without(read_yaml_mapping(made_path), "blocks", block.id) if made_path.is_file() else []
    if version is not None:
        manifest["version"] = str(version)
    return {
        PACK_MANIFEST: manifest,
        manifest["blocks"]: {"blocks": [*blocks, block_definition(block)]},
        manifest["toolbox"]: {"categories": _added_to_toolbox(categories, block)},
        MADE_FILE: {"blocks": [*made, block.to_data()]},
    }


def _write_pack(target: Path, files: dict, profile, existing):
    """Write ``files`` (``{relative path: data for YAML, or a definition's text}``) as the pack folder ``target``
    all-or-nothing; the new Pack."""
    target.parent.mkdir(parents=True, exist_ok=True)
    staging = Path(tempfile.mkdtemp(prefix=f".{target.name}.new-", dir=target.parent))
    try:
        if existing is not None:
            shutil.copytree(target, staging, dirs_exist_ok=True)
        for name, data in files.items():
            (staging / name).parent.mkdir(parents=True, exist_ok=True)
            (staging / name).write_text(data if isinstance(data, str) else dump_yaml(data), encoding="utf-8")
        try:
            pack = load_pack(staging)
            with_pack(profile, pack)
        except ManifestError as error:
            raise BlockMakerError(app_local_text("pack_not_written", pack=target.name, problem=str(error))) from None
        install_folder(staging, target)
    except OSError as error:
        raise BlockMakerError(app_local_text("pack_not_written", pack=target.name, problem=error.strerror)) from None
    finally:
        shutil.rmtree(staging, ignore_errors=True)
    return load_pack(target)


def install_folder(staging: Path, target: Path) -> None:
    """Put the folder ``staging`` in place of ``target`` (its sibling). The old one is renamed
    aside first and removed only after the new one is in place (put back if that fails): only
    between the two renames is there no pack, never half a one. Hidden folders are not read as packs."""
    old = None
    if target.exists():
        old = Path(tempfile.mkdtemp(prefix=f".{target.name}.old-", dir=target.parent))
        os.rmdir(old)
        os.rename(target, old)
    try:
        os.rename(staging, target)
    except OSError:
        if old is not None:
            os.rename(old, target)
        raise
    if old is not None:
        shutil.rmtree(old, ignore_errors=True)
