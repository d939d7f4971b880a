"""A lesson's text in one language (``lesson.LANG.md``): its title and steps, read from plain Markdown.

::

    # Drive a square               <- the title (the first line)
    An introduction (optional).
    ## Drive one side              <- a step, one per second-level heading
    The step's text, any Markdown.
    > Hint: a hint, one per quoted line
    Blocks: my_robot_drive         <- blocks to highlight (toolbox and canvas)
    Toolbox: my_robot_drive, my_robot_turn   <- optional: the only blocks the toolbox offers in this step
"""
from dataclasses import dataclass, field

from rockly_desktop.core.app_texts import app_local_text
from rockly_desktop.lessons.lesson_file import LessonError, read_text

HINT, BLOCKS, TOOLBOX = "> ", "blocks:", "toolbox:"


@dataclass
class Step:
    """One step: its ``title``, ``text`` (Markdown), ``hints``, ``blocks`` to highlight and the ``toolbox``
    it allows (None: the level's whole toolbox)."""

    title: str
    text: str = ""
    hints: list = field(default_factory=list)
    blocks: list = field(default_factory=list)
    toolbox: list = None


@dataclass
class LessonText:
    """A lesson's ``title``, ``intro`` and ``steps`` in one language."""

    title: str
    intro: str
    steps: list


def read_steps(path, block_types: set) -> LessonText:
    """The title and steps of ``path``; LessonError (file, line, what was expected) when it is broken or
    names a block ``block_types`` does not hold."""
    lines = read_text(path).splitlines()
    if not lines or not lines[0].startswith("# ") or not lines[0][2:].strip():
        raise LessonError(path, 1, app_local_text("lesson_problem_no_title"))
    title, intro, steps = lines[0][2:].strip(), [], []
    for number, line in enumerate(lines[1:], start=2):
        stripped = line.strip()
        if line.startswith("# "):
            raise LessonError(path, number, app_local_text("lesson_problem_second_title"))
        if line.startswith("## "):
            if not line[3:].strip():
                raise LessonError(path, number, app_local_text("lesson_problem_step_title"))
            steps.append(Step(line[3:].strip()))
            continue
        if not steps:
            intro.append(line)
            continue
        step = steps[-1]
        lowered = stripped.lower()
        if stripped.startswith(HINT.strip()):
            hint = stripped[1:].strip()
            if hint:
                step.hints.append(hint)
        elif lowered.startswith(BLOCKS) or lowered.startswith(TOOLBOX):
            names = [name.strip() for name in stripped.split(":", 1)[1].split(",") if name.strip()]
            unknown = [name for name in names if name not in block_types]
            if unknown or not names:
                raise LessonError(path, number, app_local_text("lesson_problem_step_blocks",
                                                               blocks=", ".join(unknown) or "-"))
            if lowered.startswith(BLOCKS):
                step.blocks.extend(names)
            else:
                step.toolbox = (step.toolbox or []) + names
        else:
            step.text = f"{step.text}\n{line}" if step.text else line
    if not steps:
        raise LessonError(path, len(lines), app_local_text("lesson_problem_no_step"))
    for step in steps:
        step.text = step.text.strip()
    return LessonText(title, "\n".join(intro).strip(), steps)
