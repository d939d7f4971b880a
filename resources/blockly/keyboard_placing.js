/**
 * Placing blocks with Blockly's own keys (T into the toolbox, arrows, Enter takes a block and Enter
 * puts it down): a block taken from the flyout while a block of the program is selected starts
 * below that block, where a child reading the program top to bottom expects the next step.
 * Blockly starts it at the first connection it can pair with the selected block, which for a
 * statement is the one above it. With nothing selected, Blockly leaves the taken block where the
 * flyout showed it, over the program's start in the view's top-left corner: it starts below the
 * program instead, at the view's left edge, and the view scrolls to it.
 */
'use strict';

const RocklyKeyboardPlacing = (() => {
  /** The block the keyboard had selected in ``workspace`` before the move began, or null. */
  function selectedBlock(workspace) {
    const element = workspace.getSvgGroup().querySelector(`.${Blockly.FocusManager.PASSIVE_FOCUS_NODE_CSS_CLASS_NAME}`);
    const node = element && element.id ? workspace.lookUpFocusableNode(element.id) : null;
    return node instanceof Blockly.BlockSvg ? node : null;
  }

  const ROOM = 64;  // workspace units between the program and a block placed below it: more than snaps

  /** Put the block ``mover`` just took from the flyout below the workspace's other blocks, in sight,
   * unless Blockly offers it at a connection. Blockly places a moved block at its start plus the way
   * moved since, so the start moves with it (its mover has no public API for that). */
  function placeBelowProgram(mover) {
    const block = mover.draggable;
    if (!block || !block.dragStrategy || block.dragStrategy.connectionCandidate) return;
    const workspace = block.workspace;
    const others = workspace.getTopBlocks(false).filter((other) => other !== block);
    if (!others.length) return;
    const view = workspace.getMetricsManager().getViewMetrics(true);
    const bottom = Math.max(...others.map((other) => other.getBoundingRectangle().bottom));
    const at = block.getRelativeToSurfaceXY();
    const by = new Blockly.utils.Coordinate(view.left + ROOM / 2 - at.x, bottom + ROOM - at.y);
    const {Coordinate} = Blockly.utils;
    mover.dragger.startLoc = Coordinate.sum(mover.dragger.startLoc, by);
    mover.startLocation = Coordinate.sum(mover.startLocation, by);
    block.moveDuringDrag(Coordinate.sum(at, by));
    mover.scrollCurrentElementIntoView();
    mover.repositionMoveIndicator();
  }

  function install() {
    const mover = Blockly.KeyboardMover.prototype;
    const startMove = mover.startMove;
    mover.startMove = function (draggable, event) {
      const fromFlyout = Boolean(draggable.workspace && draggable.workspace.isFlyout);
      const started = startMove.call(this, draggable, event);
      if (started && fromFlyout) placeBelowProgram(this);
      return started;
    };
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
