"""Errors a user can be shown as they are: each message says what is wrong and where.

``str()`` is English; ``in_language(language)`` says it in the language a person reads.
"""
from rockly_desktop.core.app_texts import app_local_text


class RocklyError(Exception):
    """Base of every error Rockly reports to a person in plain words."""

    def in_language(self, language: str) -> str:
        """The message in ``language``: errors whose words come from a catalogue override this."""
        return str(self)


class ProgramFileError(RocklyError):
    """A program file cannot be read or written; the message names the file and why."""

    def __init__(self, path, problem):
        self.path = str(path)
        self.problem = str(problem)  # English
        self._problem = problem      # a plain text or a catalogue's LocalText
        super().__init__(f"{self.path}: {problem}")

    def in_language(self, language: str) -> str:
        """``path: problem`` with the problem in ``language`` when it comes from a catalogue."""
        in_language = getattr(self._problem, "in_language", None)
        return f"{self.path}: {in_language(language)}" if in_language is not None else str(self)


class ManifestError(RocklyError):
    """A robot profile's files are invalid: names the file, the field and what is wrong."""

    def __init__(self, path, field, problem):
        self.path = str(path)
        self.field = field
        self.problem = problem
        where = f"{self.path}: {field}" if field else self.path
        super().__init__(f"{where}: {problem}")


class UnknownBlocksError(RocklyError):
    """A program uses block types that no installed profile provides (``missing_packs``: the
    (id, version) of block packs the program records that are not installed)."""

    def __init__(self, block_types, profile_id, profile_installed, missing_packs=()):
        self.block_types = sorted(block_types)
        self.profile_id = profile_id
        self.profile_installed = profile_installed
        self.missing_packs = tuple(missing_packs)
        if self.missing_packs:
            hint = app_local_text("unknown_blocks_pack_missing", packs=", ".join(
                f"'{pack_id}' {version}" for pack_id, version in self.missing_packs))
        elif profile_id is None:
            hint = app_local_text("unknown_blocks_install")
        elif profile_installed:
            hint = app_local_text("unknown_blocks_newer", profile=profile_id)
        else:
            hint = app_local_text("unknown_blocks_not_installed", profile=profile_id)
        self.message = app_local_text("unknown_blocks", blocks=", ".join(self.block_types), hint=hint)
        super().__init__(str(self.message))

    def in_language(self, language: str) -> str:
        """The message in ``language``."""
        return self.message.in_language(language)


class RobotCommandError(RocklyError):
    """A robot command cannot be done: a bad argument, a failed goal, an unanswered service.

    The message is a text of a catalogue (a ``core.catalogue.LocalText``: the profile's own,
    from its ``locale/`` folder, or Rockly's), which a run shows in its language; ``str()`` is
    English. A plain string is shown as it is in every language.
    """

    def __init__(self, message="", *args):
        super().__init__(message, *args)
        self.message = message

    def __str__(self) -> str:
        return str(self.message) if not self.args[1:] else super().__str__()

    def in_language(self, language: str) -> str:
        """The message in ``language`` (English where its catalogue has no translation)."""
        in_language = getattr(self.message, "in_language", None)
        return in_language(language) if in_language is not None else str(self)


class RobotTimeout(RobotCommandError):
    """The robot did not answer in time."""


class ProgramStopped(RocklyError):
    """Raised inside a running program (at a block or inside a robot wait) when it is stopped."""


class RobotConnectionLost(RobotCommandError):
    """The robot (its ROS master or a node it needs) stopped answering."""


class DefinitionNotLearnt(RobotCommandError):
    """The definition of a type the robot offers could not be learnt from it: the message says why and
    what to do (the block maker shows it in place of the type's fields)."""
