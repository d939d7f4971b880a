"""Putting installed block packs into the robot profile they add to.

The merged profile is an ordinary Profile: the editor page gets the packs' blocks and
generators with the profile's own (``Profile.editor_config``), and its toolbox gets each
pack's categories (blocks of a category named like one of the profile's own join it; other
categories come after the profile's own, before the shared ones).
"""
from dataclasses import dataclass, field, replace

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.profiles.packs.validation import BlockMakerError


@dataclass(frozen=True)
class PackInfo:
    """What a merged profile knows of one of its packs: id, version, name, block types, the
    ROS name each made block uses (a teacher switching that part off hides the block), and the
    folder of its ROS definitions (None: it has none)."""

    id: str
    version: str
    name: object
    block_types: frozenset
    interfaces: dict = field(default_factory=dict)
    message_folder: object = None


def _english(name) -> str:
    return name.get("en") if isinstance(name, dict) else name


def _merged_categories(categories: list, additions: list) -> list:
    merged = [dict(category) for category in categories]
    for addition in additions:
        same = next((category for category in merged if "shared" not in category and "contents" in category
                     and _english(category["name"]) == _english(addition["name"])), None)
        if same is not None:
            same["contents"] = [*same["contents"], *addition["contents"]]
            continue
        position = next((index for index, category in enumerate(merged) if "shared" in category), len(merged))
        merged.insert(position, addition)
    return merged


def merge_problem(profile, pack):
    """Why ``pack`` cannot go into ``profile`` (a LocalText), or None."""
    if pack.adds_to != profile.id:
        return app_local_text("pack_adds_to_other", pack=pack.id, other=pack.adds_to, profile=profile.id)
    clash = sorted(pack.block_types & profile.block_types)
    if clash:
        owner = profile.pack_of(clash[0])
        if owner is not None:
            return app_local_text("pack_block_id_in_pack", pack=owner, id=clash[0])
        return app_local_text("pack_block_id_in_profile", profile=profile.id, id=clash[0])
    return None


def with_pack(profile, pack):
    """``profile`` with ``pack``'s blocks and categories; BlockMakerError when it cannot take them."""
    problem = merge_problem(profile, pack)
    if problem is not None:
        raise BlockMakerError(problem)
    info = PackInfo(pack.id, pack.version, pack.name, frozenset(pack.block_types),
                    {made.id: made.interface for made in pack.made if made.id in pack.block_types},
                    pack.message_folder)
    return replace(profile, blocks=profile.blocks + pack.blocks,
                   toolbox_categories=_merged_categories(profile.toolbox_categories, pack.toolbox_categories),
                   packs=(*profile.packs, info))


def with_packs(profile, packs) -> tuple:
    """``(profile with every pack of ``packs`` that adds to it, errors of those that could not go in)``."""
    errors = []
    for pack in sorted(packs, key=lambda pack: pack.id):
        if pack.adds_to != profile.id:
            continue
        try:
            profile = with_pack(profile, pack)
        except BlockMakerError as error:
            errors.append(BlockMakerError(app_local_text("pack_broken", pack=pack.id, problem=error.problems[0])))
    return profile, errors
