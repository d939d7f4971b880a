"""Errors a user can be shown as they are: each message says what is wrong and where."""


class RocklyError(Exception):
    """Base of every error Rockly reports to a person in plain words."""


class ProgramFileError(RocklyError):
    """A program file cannot be read or written; the message names the file and why."""

    def __init__(self, path, problem):
        self.path = str(path)
        self.problem = problem
        super().__init__(f"{self.path}: {problem}")


class ManifestError(RocklyError):
    """A robot profile's files are invalid: names the file, the field and what is wrong."""

    def __init__(self, path, field, problem):
        self.path = str(path)
        self.field = field
        self.problem = problem
        where = f"{self.path}: {field}" if field else self.path
        super().__init__(f"{where}: {problem}")


class UnknownBlocksError(RocklyError):
    """A program uses block types that no installed profile provides."""

    def __init__(self, block_types, profile_id, profile_installed):
        self.block_types = sorted(block_types)
        self.profile_id = profile_id
        self.profile_installed = profile_installed
        listed = ", ".join(self.block_types)
        if profile_id is None:
            hint = "Install the robot profile that provides them, then open the program again."
        elif profile_installed:
            hint = f"The robot profile '{profile_id}' does not provide them; a newer version of it may."
        else:
            hint = f"It was made for the robot profile '{profile_id}', which is not installed."
        super().__init__(f"This program uses blocks that no installed profile knows: {listed}. {hint}")


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
