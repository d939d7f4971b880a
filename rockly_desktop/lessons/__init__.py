"""Lessons: a robot task for a child, with goals the built-in simulator checks (``docs/lessons.md``).

The API the window's Lessons dock, ``rockly lessons`` and the tests share (no Qt anywhere here):

* ``library.LessonLibrary.discover(profiles)`` finds every lesson (shipped, the user's, imported packs); its
  ``by_robot_and_level()`` and ``for_robot(robot, level)`` list them, ``get(id)`` finds one, ``problems``
  holds the broken ones; ``lesson.load_lesson(folder, profiles)`` reads one, raising ``LessonError``
  (file, line, what was expected, in any language) for a broken one. A ``Lesson`` gives its title and
  steps per language (``steps.Step``: text, hints, blocks to highlight, the toolbox it allows), its
  start program and its goals;
* ``check.check_program(lesson, program)`` runs a program's generated code (a ``check.GeneratedProgram``:
  the page's run code, the workspace JSON, block types by id) on the lesson's simulated robot in
  simulated time and returns a ``CheckResult``: per goal whether it passed, in words a child reads
  (LocalTexts), how the run ended, and ``failing``: the simulated time and block of the first failing
  moment; with ``record=PATH`` it also writes the run as a recording in simulated time, for a replay at
  that moment. It blocks until done (about a second): call it off the window's thread;
* ``parallel.ParallelChecks``: many programs in worker processes; ``archive``: lessons shared as one zip.

A profile adds goal kinds by naming a list of ``goals.LessonGoal`` classes in its manifest's
``lesson_goals`` (the SDK exports the base class).
"""
