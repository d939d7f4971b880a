/**
 * A lesson step's blocks, marked wherever a child looks for them: the toolbox categories holding them,
 * the blocks in an open category's flyout and those already on the canvas (CSS class rocklyLesson).
 * ``RocklyLessonMarks.set(workspace, types)`` marks the blocks of ``types`` ([] clears); ``watch(workspace)``
 * keeps the marks on blocks made later (a category opened, a block dragged in); ``refresh(workspace)`` marks
 * a new toolbox's categories.
 */
const RocklyLessonMarks = (() => {
  const MARK = 'rocklyLesson';
  let marked = new Set();

  function markBlocks(space) {
    if (!space) return;
    for (const block of space.getAllBlocks(false)) {
      const root = block.getSvgRoot && block.getSvgRoot();
      if (root) root.classList.toggle(MARK, marked.has(block.type));
    }
  }

  function holds(contents) {
    return (contents || []).some((item) => (item.kind || '').toLowerCase() === 'block' && marked.has(item.type));
  }

  function markCategories(workspace) {
    const toolbox = workspace.getToolbox && workspace.getToolbox();
    if (!toolbox) return;
    for (const item of toolbox.getToolboxItems()) {
      const div = item.getDiv && item.getDiv();
      if (div && item.getContents) div.classList.toggle(MARK, holds(item.getContents()));
    }
  }

  function markAll(workspace) {
    markBlocks(workspace);
    const flyout = workspace.getFlyout && workspace.getFlyout();
    markBlocks(flyout && flyout.getWorkspace());
    markCategories(workspace);
  }

  return {
    set(workspace, types) {
      marked = new Set(types || []);
      markAll(workspace);
      return [...marked];
    },
    refresh(workspace) {
      if (marked.size) markAll(workspace);
    },
    watch(workspace) {
      workspace.addChangeListener((event) => {
        if (!marked.size) return;
        if (event.type === Blockly.Events.TOOLBOX_ITEM_SELECT || event.type === Blockly.Events.BLOCK_CREATE
            || event.type === Blockly.Events.FINISHED_LOADING) {
          setTimeout(() => markAll(workspace), 0);  // once the flyout's (or the new) blocks are drawn
        }
      });
    },
  };
})();
