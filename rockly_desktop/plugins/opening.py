"""Reading a program file for the editor: which profile it needs and whether every block is known.

Everything is checked before the editor is touched, so a bad file never replaces the
program on screen.
"""
from dataclasses import dataclass
from pathlib import Path

from rockly_desktop.core.errors import UnknownBlocksError
from rockly_desktop.core.program import load_program, read_text_file
from rockly_desktop.core.workspace_blocks import (
    block_types_in_workspace, block_types_in_xml, parse_blockly_xml, rename_legacy_fields, xml_to_text,
)
from rockly_desktop.plugins.profile import Profile
from rockly_desktop.plugins.registry import ProfileRegistry

XML_SUFFIX = ".xml"


@dataclass(frozen=True)
class ProgramToOpen:
    """A program file that passed every check: its profile and its content for the editor."""

    path: Path
    profile: Profile
    workspace: dict = None
    xml: str = None

    @property
    def is_import(self) -> bool:
        """True for a first-Rockly XML program (it becomes an unsaved Rockly program)."""
        return self.xml is not None


def _best_profile_for(block_types, registry: ProfileRegistry, fallback: Profile) -> Profile:
    """The installed profile defining most of ``block_types`` (the fallback if none does)."""
    scored = [(len(block_types & profile.block_types), profile) for profile in registry.profiles.values()]
    best_score, best = max(scored, key=lambda pair: pair[0], default=(0, fallback))
    return best if best_score else fallback


def read_program_to_open(path, registry: ProfileRegistry, builtin_types, fallback: Profile) -> ProgramToOpen:
    """Read a ``.rockly`` or first-Rockly ``.xml`` file and check it can be shown.

    ``builtin_types`` are the block types Blockly itself defines. Raises
    ProgramFileError for a bad file and UnknownBlocksError when blocks are missing.
    """
    path = Path(path)
    builtin_types = set(builtin_types)
    if path.suffix.lower() == XML_SUFFIX:
        root = parse_blockly_xml(read_text_file(path), path)
        types = set(block_types_in_xml(root))
        profile = _best_profile_for(types - builtin_types, registry, fallback)
        unknown = types - builtin_types - profile.block_types
        if unknown:
            raise UnknownBlocksError(unknown, None, False)
        rename_legacy_fields(root, profile.legacy_fields)
        return ProgramToOpen(path, profile, xml=xml_to_text(root))

    program = load_program(path)
    types = set(block_types_in_workspace(program.workspace))
    installed = program.profile_id in registry.profiles
    if installed:
        profile = registry.get(program.profile_id)
        unknown = types - builtin_types - profile.block_types
    else:
        profile = _best_profile_for(types - builtin_types, registry, fallback)
        unknown = types - builtin_types - registry.all_block_types()
    if unknown:
        raise UnknownBlocksError(unknown, program.profile_id, installed)
    return ProgramToOpen(path, profile, workspace=program.workspace)
