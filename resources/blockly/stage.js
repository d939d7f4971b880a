/**
 * The stage (View → Stage, and the kiosk): the simulator large, the blocks beside it in a narrow
 * editor. There the toolbox's flyout and the zoom controls never cover the blocks a child is using:
 * - the zoom buttons and the trashcan are put away (the wheel still zooms, and a block dropped on
 *   the toolbox is deleted), and where they were is no place a dropped block disappears into;
 * - the flyout's blocks are drawn at the workspace's scale in every category, as off stage: a wide
 *   block makes its flyout wider, never its text smaller;
 * - while the flyout is out, the program moves right of it, and back when it closes; a block being
 *   dragged or taken with the keys out of it (which closes it) stays where it is on screen while the
 *   program comes back.
 */
'use strict';

const RocklyStage = (() => {
  const GAP = 16;                 // px between the flyout's edge and the program
  let workspace = null;
  let on = false;
  let shifted = 0;                // px the program was moved right for the flyout
  let homeLeft = null;            // the program's left edge (page px) before that

  function install(ws) {
    workspace = ws;
    for (const control of [ws.trashcan, ws.zoomControls_]) {
      if (!control || !control.getClientRect) continue;
      const ownRect = control.getClientRect.bind(control);
      control.getClientRect = () => (on ? null : ownRect());
    }
    ws.addChangeListener((event) => {
      if (on && event.type === Blockly.Events.TOOLBOX_ITEM_SELECT) requestAnimationFrame(followFlyout);
    });
    addEventListener('resize', () => on && requestAnimationFrame(followFlyout));  // the stage settling, a window resized
  }

  /** Blockly lets the program move at most half a view away from the view's edge: on stage it may
   * move a view further, to the right of an open flyout. */
  class StageMetrics extends Blockly.MetricsManager {
    getPaddedContent_(view, content) {
      const padded = super.getPaddedContent_(view, content);
      return on ? {...padded, left: padded.left - view.width} : padded;
    }
  }

  /** The left edge (page px) of the top blocks that are on screen (not one being moved), or null. */
  function programLeft() {
    const edges = workspace.getTopBlocks(false).filter((block) => !block.isDragging())
        .map((block) => block.getSvgRoot().getBoundingClientRect())
        .filter((box) => box.right > 0 && box.left < innerWidth && box.bottom > 0 && box.top < innerHeight)
        .map((box) => box.left);
    return edges.length ? Math.min(...edges) : null;
  }

  function followFlyout() {
    const flyout = workspace.getFlyout();
    const out = Boolean(flyout && flyout.isVisible());
    const left = programLeft();
    if (!out) {
      // Back where it was: Blockly may have scrolled meanwhile (a block taken with the keys is
      // scrolled into sight as the flyout closes), and that scroll was only for the flyout's sake.
      if (shifted) moveProgram(homeLeft !== null && left !== null ? homeLeft - left : -shifted);
      shifted = 0;
      return;
    }
    const edge = workspace.getMetricsManager().getAbsoluteMetrics().left + flyout.getWidth() + GAP;
    if (left === null) return;
    if (!shifted) homeLeft = left;
    // Right of this flyout, and no further than that from where it was (a narrower category after a wider one).
    const wanted = Math.max(edge, homeLeft);
    if (left < edge || (shifted && left > wanted)) moveProgram(wanted - left);
  }

  function moveProgram(dx) {
    if (!dx) return;
    workspace.scroll(workspace.scrollX + dx, workspace.scrollY);
    shifted += dx;
    keepDraggedInPlace(dx);
  }

  /** After a scroll by ``dx`` px during a drag or a keyboard move (taking a block from the flyout
   * closes it): the block where it was on screen, under the pointer, in sight. Blockly puts a dragged
   * block at the drag's start plus the way moved since, in workspace units, so the scroll is taken off
   * that start; neither its gesture nor its keyboard mover has public API for it. A block the keys
   * show at a connection stays at that connection. */
  function keepDraggedInPlace(dx) {
    const mover = Blockly.KeyboardMover.mover;
    const keyboard = mover.isMoving();
    const dragger = keyboard ? mover.dragger : workspace.currentGesture_ && workspace.currentGesture_.dragger;
    if (!dragger || !dragger.startLoc || !workspace.isDragging()) return;
    const strategy = dragger.draggable.dragStrategy;
    if (keyboard && strategy && strategy.connectionCandidate) return;
    const back = -dx / workspace.scale;
    const {Coordinate} = Blockly.utils;
    const shift = (at) => new Coordinate(at.x + back, at.y);
    dragger.startLoc = shift(dragger.startLoc);
    if (keyboard) mover.startLocation = shift(mover.startLocation);
    dragger.draggable.drag(shift(dragger.draggable.getRelativeToSurfaceXY()));
  }

  /** Go on stage or leave it. */
  function set(active) {
    if (active === on) return;
    if (!active) moveProgram(-shifted);
    on = active;
    document.body.classList.toggle('rocklyStage', on);
  }

  return {install, set, active: () => on, MetricsManager: StageMetrics};
})();
