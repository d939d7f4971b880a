"""The agent on the robot (``rockly agent``): a library of programs, one run at a time in a child process,
and a JSON-lines interface over TCP that clients (``rockly robot ...``, ``AgentClient``) use. Qt-free."""
