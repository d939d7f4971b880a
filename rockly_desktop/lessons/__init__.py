"""Lessons: a robot task for a child, with goals the built-in simulator checks (``docs/lessons.md``).

The API the window's Lessons dock, ``rockly lessons`` and the tests share (no Qt anywhere here):

* ``library.LessonLibrary.discover(profiles)`` finds every lesson (shipped, the user's, imported packs);
  ``library.by_robot_and_level()`` lists them; ``lesson.load_lesson(folder, profiles)`` reads one,
  raising ``LessonError`` (file, line, what was expected) for a broken one;
* ``check.check_program(lesson, program)`` runs a program's generated code (a ``check.GeneratedProgram``)
  on the lesson's simulated robot in simulated time and returns a ``CheckResult``: per goal whether it
  passed, in words a child reads, and the simulated time and block of the failing moment;
* ``archive``: lessons shared as one zip (``rockly lessons export/import``).

A profile adds goal kinds by naming a list of ``goals.LessonGoal`` classes in its manifest's
``lesson_goals`` (the SDK exports the base class).
"""
