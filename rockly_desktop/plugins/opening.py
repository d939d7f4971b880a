"""Reading a program file for the editor: the profile it needs and what the editor must do.

The file is read and checked here; whether every block exists is checked by the editor
page itself (it knows Blockly's own blocks), which refuses a program with unknown
blocks before touching the workspace. ``unknown_blocks_error`` words that refusal.
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
    """A program file that was read: the profile to show it with, and its content."""

    path: Path
    profile: Profile
    workspace: dict = None
    xml: str = None
    declared_profile: str = None
    breakpoints: tuple = ()

    @property
    def is_import(self) -> bool:
        """True for a first-Rockly XML program (it becomes an unsaved Rockly program)."""
        return self.xml is not None

    def editor_call(self) -> tuple:
        """The editor page call that shows this program: (name, args)."""
        if self.is_import:
            return "importXml", {"xml": self.xml}
        return "load", {"workspace": self.workspace, "breakpoints": list(self.breakpoints)}


def _best_profile_for(block_types, registry: ProfileRegistry, fallback: Profile) -> Profile:
    """The installed profile defining most of ``block_types`` (the fallback if none does)."""
    scored = [(len(block_types & profile.own_block_types), profile) for profile in registry.profiles.values()]
    best_score, best = max(scored, key=lambda pair: pair[0], default=(0, fallback))
    return best if best_score else fallback


def read_program_to_open(path, registry: ProfileRegistry, fallback: Profile) -> ProgramToOpen:
    """Read a ``.rockly`` or first-Rockly ``.xml`` file; raise ProgramFileError if it is bad.

    The profile is the one the program names, or for XML (and programs of a profile that
    is not installed) the installed one defining most of its blocks, else ``fallback``.
    """
    path = Path(path)
    if path.suffix.lower() == XML_SUFFIX:
        root = parse_blockly_xml(read_text_file(path), path)
        profile = _best_profile_for(set(block_types_in_xml(root)), registry, fallback)
        rename_legacy_fields(root, profile.legacy_fields)
        return ProgramToOpen(path, profile, xml=xml_to_text(root))
    program = load_program(path)
    if program.profile_id in registry.profiles:
        profile = registry.get(program.profile_id)
    else:
        profile = _best_profile_for(set(block_types_in_workspace(program.workspace)), registry, fallback)
    return ProgramToOpen(path, profile, workspace=program.workspace, declared_profile=program.profile_id,
                         breakpoints=tuple(program.breakpoints))


def unknown_blocks_error(program: ProgramToOpen, unknown_types, registry: ProfileRegistry) -> UnknownBlocksError:
    """The error for a program the editor refused because of ``unknown_types``."""
    declared = program.declared_profile
    return UnknownBlocksError(unknown_types, declared, declared in registry.profiles if declared else False)
