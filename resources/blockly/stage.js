/**
 * The stage (View → Stage, and the kiosk): the simulator large, the blocks beside it in a narrow
 * editor. There the toolbox's flyout and the zoom controls never cover the blocks a child is using:
 * - the zoom buttons and the trashcan are put away (the wheel still zooms, and a block dropped on
 *   the toolbox is deleted), and where they were is no place a dropped block disappears into;
 * - the flyout's blocks are drawn at the workspace's scale in every category, as off stage: a wide
 *   block makes its flyout wider, never its text smaller;
 * - while the flyout is out, the program moves right of it, and back when it closes; a block being
 *   dragged out of it (which closes it) stays under the pointer while the program comes back.
 */
'use strict';

const RocklyStage = (() => {
  const GAP = 16;                 // px between the flyout's edge and the program
  let workspace = null;
  let on = false;
  let shifted = 0;                // px the program was moved right for the flyout

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

  /** The left edge (page px) of the top blocks that are on screen, or null. */
  function programLeft() {
    const edges = workspace.getTopBlocks(false).map((block) => block.getSvgRoot().getBoundingClientRect())
        .filter((box) => box.right > 0 && box.left < innerWidth && box.bottom > 0 && box.top < innerHeight)
        .map((box) => box.left);
    return edges.length ? Math.min(...edges) : null;
  }

  function followFlyout() {
    const flyout = workspace.getFlyout();
    const out = Boolean(flyout && flyout.isVisible());
    if (!out) {
      moveProgram(-shifted);
      return;
    }
    const left = programLeft();
    const edge = workspace.getMetricsManager().getAbsoluteMetrics().left + flyout.getWidth() + GAP;
    if (left !== null && left < edge) moveProgram(edge - left);
  }

  function moveProgram(dx) {
    if (!dx) return;
    workspace.scroll(workspace.scrollX + dx, workspace.scrollY);
    shifted += dx;
    keepDragUnderPointer(dx);
  }

  /** After a scroll by ``dx`` px during a drag (a block taken from the flyout closes it): the dragged
   * block back under the pointer. Blockly puts it at the drag's start plus the pointer's way since, in
   * workspace units, so the scroll is taken off that start; its gesture has no public API for that. */
  function keepDragUnderPointer(dx) {
    const dragger = workspace.currentGesture_ && workspace.currentGesture_.dragger;
    if (!dragger || !dragger.startLoc || !workspace.isDragging()) return;
    const back = -dx / workspace.scale;
    const {Coordinate} = Blockly.utils;
    dragger.startLoc = new Coordinate(dragger.startLoc.x + back, dragger.startLoc.y);
    const at = dragger.draggable.getRelativeToSurfaceXY();
    dragger.draggable.drag(new Coordinate(at.x + back, at.y));
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
