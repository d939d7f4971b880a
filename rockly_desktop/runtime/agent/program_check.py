"""Reading a sent program's standalone text in a child process with a memory limit of its own.

Python's parser takes about a kilobyte of memory per byte of some texts (4 MB of ``a`` lines took the agent to
3.5 GB, and a STOP waited 12 s behind it), so the agent never parses what a client sent in its own process: a
child (``python -I``: no site packages, no Rockly, nothing of the agent's) parses it under ``CHECK_MEMORY_BYTES``
of address space and ``CHECK_SECONDS``, and hands back ``PROGRAM`` and ``RUN_CODE`` as JSON. What the child
cannot read, or dies reading, is refused as no program.
"""
import json
import subprocess
import sys

from rockly_desktop.runtime.agent.protocol import AgentRefusal

CHECK_MEMORY_BYTES = 1024 * 1024 * 1024
CHECK_SECONDS = 30.0

# The child: limits itself first, then reads the text as data (nothing in it runs).
_CHILD = f"""
import ast, json, resource, sys
resource.setrlimit(resource.RLIMIT_AS, ({CHECK_MEMORY_BYTES}, {CHECK_MEMORY_BYTES}))
text = sys.stdin.buffer.read().decode("utf-8")
found = {{}}
for node in ast.parse(text).body:
    if isinstance(node, ast.Assign) and len(node.targets) == 1 and isinstance(node.targets[0], ast.Name):
        try:
            found[node.targets[0].id] = ast.literal_eval(node.value)
        except (ValueError, TypeError, SyntaxError, MemoryError, RecursionError):
            continue
sys.stdout.write(json.dumps([found.get("PROGRAM"), found.get("RUN_CODE")]))
"""


def standalone_parts(text: str) -> tuple:
    """``(PROGRAM, RUN_CODE)`` of a standalone file's ``text``, read in a child process; AgentRefusal
    ``agent_not_standalone`` for a text that is no standalone program or too much to read."""
    try:
        data = text.encode("utf-8")
    except UnicodeEncodeError:
        raise AgentRefusal("agent_not_standalone") from None
    try:
        done = subprocess.run([sys.executable, "-I", "-c", _CHILD], input=data, capture_output=True,
                              timeout=CHECK_SECONDS, check=False)
    except (OSError, subprocess.TimeoutExpired):
        raise AgentRefusal("agent_not_standalone") from None
    try:
        program, run_code = json.loads(done.stdout) if done.returncode == 0 else (None, None)
    except (ValueError, TypeError):
        program, run_code = None, None
    if not isinstance(program, dict) or not isinstance(run_code, str) or not isinstance(program.get("profile"), dict):
        raise AgentRefusal("agent_not_standalone")
    return program, run_code
