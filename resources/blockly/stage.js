/**
 * The stage (View → Stage, and the kiosk): the simulator large, the blocks beside it in a narrow
 * editor. There the toolbox's flyout and the zoom controls never cover the blocks a child is using:
 * - the zoom buttons and the trashcan are put away (the wheel still zooms, and a block dropped on
 *   the toolbox is deleted), and where they were is no place a dropped block disappears into;
 * - the flyout's blocks are drawn at the desk's scale in every category, as off stage: a wide block
 *   makes its flyout wider, never its text smaller;
 * - while the flyout is out, the program moves right of it, and back when it closes; while a block
 *   taken out of it (which closes it) is dragged or moved with the keys, the program stays where it is,
 *   and both come back together once the block is dropped;
 * - the program's blocks are drawn larger, for an audience (the desk's zoom comes back when the stage is
 *   left); the flyouts stay at the desk's scale, for the person at the laptop.
 */
'use strict';

const RocklyStage = (() => {
  const GAP = 16;                 // px between the flyout's edge and the program
  const STAGE_SCALE = 1.25;       // the workspace's scale on stage: text read from a few metres (the desk's is 0.8)
  let workspace = null;
  let on = false;
  let shifted = 0;                // px the program was moved right for the flyout
  let homeLeft = null;            // the program's left edge (page px) before that
  let deskScale = null;           // the workspace's scale before the stage

  function install(ws) {
    workspace = ws;
    const flyout = ws.getFlyout();
    if (flyout) {  // the flyout stays at the desk's size on stage: it is read by the person at the laptop
      const ownScale = flyout.getFlyoutScale.bind(flyout);
      flyout.getFlyoutScale = () => (on && deskScale !== null ? Math.min(ownScale(), deskScale) : ownScale());
    }
    for (const control of [ws.trashcan, ws.zoomControls_]) {
      if (!control || !control.getClientRect) continue;
      const ownRect = control.getClientRect.bind(control);
      control.getClientRect = () => (on ? null : ownRect());
    }
    ws.addChangeListener((event) => {
      const moved = event.type === Blockly.Events.BLOCK_DRAG && !event.isStart;
      if (on && (event.type === Blockly.Events.TOOLBOX_ITEM_SELECT || moved)) requestAnimationFrame(followFlyout);
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
      // A block taken out of the flyout (which closes it) is being moved: the program stays where the person
      // sees it until the block is dropped, then both come back together (BLOCK_DRAG's end calls again).
      if (workspace.isDragging()) return;
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
  }

  /** Zoom to ``scale`` around the view's top left corner (right of the toolbox), where a program starts (Blockly's
   * setScale zooms around the centre, and the program's start went out of sight). */
  function scaleTo(scale) {
    const speed = workspace.options.zoomOptions.scaleSpeed;
    const corner = workspace.getMetricsManager().getAbsoluteMetrics();  // right of the toolbox
    workspace.zoom(corner.left, corner.top, Math.log(scale / workspace.scale) / Math.log(speed));
  }

  /** Go on stage or leave it. */
  function set(active) {
    if (active === on) return;
    if (!active) moveProgram(-shifted);
    if (active) {
      deskScale = workspace.scale;
      if (deskScale < STAGE_SCALE) scaleTo(STAGE_SCALE);
    } else if (deskScale !== null) {
      scaleTo(deskScale);
      deskScale = null;
    }
    on = active;
    document.body.classList.toggle('rocklyStage', on);
    const flyout = workspace.getFlyout();
    if (flyout && flyout.isVisible()) flyout.reflow();
  }

  return {install, set, active: () => on, deskScale: () => deskScale, MetricsManager: StageMetrics};
})();
