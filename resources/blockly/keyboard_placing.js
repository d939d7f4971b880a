/**
 * Placing blocks with Blockly's own keys (T into the toolbox, arrows, Enter takes a block and Enter
 * puts it down): a block taken from the flyout while a block of the program is selected starts
 * below that block, where a child reading the program top to bottom expects the next step.
 * Blockly starts it at the first connection it can pair with the selected block, which for a
 * statement is the one above it.
 */
'use strict';

const RocklyKeyboardPlacing = (() => {
  /** The block the keyboard had selected in ``workspace`` before the move began, or null. */
  function selectedBlock(workspace) {
    const element = workspace.getSvgGroup().querySelector(`.${Blockly.FocusManager.PASSIVE_FOCUS_NODE_CSS_CLASS_NAME}`);
    const node = element && element.id ? workspace.lookUpFocusableNode(element.id) : null;
    return node instanceof Blockly.BlockSvg ? node : null;
  }

  function install() {
    const strategy = Blockly.dragging.BlockDragStrategy.prototype;
    const initialCandidate = strategy.getInitialCandidate;
    strategy.getInitialCandidate = function () {
      const candidate = initialCandidate.call(this);
      const selected = selectedBlock(this.workspace);
      if (!candidate || !selected || candidate.neighbour !== selected.previousConnection) return candidate;
      const below = this.allConnectionPairs.find((pair) => pair.neighbour === selected.nextConnection);
      return below ? {...below, distance: 0} : candidate;
    };
  }

  return {install};
})();
