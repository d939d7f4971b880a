"""Looking inside the editor page from tests (the app itself only uses the JSON channel)."""
import json


def run_js(qtbot, view, script: str):
    """Evaluate ``script`` in the editor page and return its (JSON-able) value."""
    holder = []
    wrapped = (f"(() => {{ try {{ return JSON.stringify({{value: ({script})}}); }} "
               "catch (e) { return JSON.stringify({error: String(e)}); } })()")
    view.page().runJavaScript(wrapped, 0, holder.append)
    qtbot.waitUntil(lambda: bool(holder), timeout=10000)
    answer = json.loads(holder[0])
    if "error" in answer:
        raise AssertionError(f"page script failed: {answer['error']}")
    return answer.get("value")


def call_page(qtbot, view, name: str, args=None, timeout=15000):
    """Run a page call on an EditorView and wait for its answer (AssertionError on a page error)."""
    answers = []
    view.call(name, args, lambda result, error: answers.append((result, error)))
    qtbot.waitUntil(lambda: bool(answers), timeout=timeout)
    result, error = answers[0]
    if error:
        raise AssertionError(f"the page answered '{name}' with an error: {error}")
    return result


def toolbox_names(qtbot, view) -> list:
    """The toolbox category names as shown."""
    return run_js(qtbot, view, "Blockly.getMainWorkspace().getToolbox().getToolboxItems()"
                               ".filter(i => i.getName).map(i => i.getName())")


def add_block_as_user(qtbot, view, block_type: str) -> str:
    """Create a block the way a drag from the toolbox does (events on); return its id."""
    return run_js(qtbot, view, f"""(() => {{
        const ws = Blockly.getMainWorkspace();
        const b = ws.newBlock({block_type!r});
        b.initSvg(); b.render(); b.moveBy(40, 40);
        Blockly.Events.fire(new (Blockly.Events.get(Blockly.Events.BLOCK_CREATE))(b));
        return b.id; }})()""")


def block_types_on_page(qtbot, view) -> list:
    """Types of all blocks in the workspace."""
    return run_js(qtbot, view, "Blockly.getMainWorkspace().getAllBlocks(false).map(b => b.type).sort()")


def print_value(qtbot, view, block_id: str) -> str:
    """Snap the value block ``block_id`` into a new print block, as a person would (a loose value is not run);
    return the print block's id."""
    return run_js(qtbot, view, f"""(() => {{
        const ws = Blockly.getMainWorkspace();
        const p = ws.newBlock('text_print');
        p.initSvg(); p.render();
        Blockly.Events.fire(new (Blockly.Events.get(Blockly.Events.BLOCK_CREATE))(p));
        p.getInput('TEXT').connection.connect(ws.getBlockById({block_id!r}).outputConnection);
        return p.id; }})()""")


# The program's top-left block (the first top block in reading order) and the part of the workspace on screen.
START_IN_VIEW = """(() => {
    const ws = Blockly.getMainWorkspace();
    const view = ws.getMetricsManager().getViewMetrics(true);
    const first = ws.getTopBlocks(true)[0].getBoundingRectangle();
    return {view: [view.left, view.top, view.left + view.width, view.top + view.height],
            block: [first.left, first.top, first.right, first.bottom]};
})()"""
