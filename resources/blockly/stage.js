/**
 * The stage (View → Stage, and the kiosk): the simulator large, the blocks beside it in a narrow
 * editor. There the toolbox's flyout and the zoom controls never cover the blocks a child is using:
 * - the zoom buttons and the trashcan are put away (the wheel still zooms, and a block dropped on
 *   the toolbox is deleted), and where they were is no place a dropped block disappears into;
 * - the flyout's blocks are drawn smaller where it would take more than half of the view (fitted
 *   again whenever the view's width changes);
 * - while the flyout is out, the program moves right of it, and back when it closes;
 * - the blocks are drawn larger, for an audience (the desk's zoom comes back when the stage is left).
 */
'use strict';

const RocklyStage = (() => {
  const GAP = 16;                 // px between the flyout's edge and the program
  const FLYOUT_SHARE = 0.5;       // of the view's width the flyout may take on stage
  const MIN_FLYOUT_SCALE = 0.5;   // smaller blocks are not read at a glance
  const STAGE_SCALE = 1.25;       // the workspace's scale on stage: text read from a few metres (the desk's is 0.8)
  let workspace = null;
  let on = false;
  let shifted = 0;                // px the program was moved right for the flyout
  let deskScale = null;           // the workspace's scale before the stage

  function install(ws) {
    workspace = ws;
    const flyout = ws.getFlyout();
    if (flyout) {
      const ownScale = flyout.getFlyoutScale.bind(flyout);
      flyout.getFlyoutScale = () => (on ? fittedScale(flyout, ownScale()) : ownScale());
    }
    for (const control of [ws.trashcan, ws.zoomControls_]) {
      if (!control || !control.getClientRect) continue;
      const ownRect = control.getClientRect.bind(control);
      control.getClientRect = () => (on ? null : ownRect());
    }
    ws.addChangeListener((event) => {
      if (on && event.type === Blockly.Events.TOOLBOX_ITEM_SELECT) requestAnimationFrame(followFlyout);
    });
    addEventListener('resize', () => on && requestAnimationFrame(refit));  // the stage settling, a window resized
  }

  /** After the view's size changed: the open flyout's scale fitted to the new width (Blockly only
   * moves a flyout on a resize; one opened before the page had its stage size stayed too wide),
   * and the program right of it. */
  function refit() {
    const flyout = workspace.getFlyout();
    if (flyout && flyout.isVisible() && flyout.getWorkspace().scale !== flyout.getFlyoutScale()) flyout.reflow();
    followFlyout();
  }

  /** Blockly lets the program move at most half a view away from the view's edge: on stage it may
   * move a view further, to the right of an open flyout. */
  class StageMetrics extends Blockly.MetricsManager {
    getPaddedContent_(view, content) {
      const padded = super.getPaddedContent_(view, content);
      return on ? {...padded, left: padded.left - view.width} : padded;
    }
  }

  /** The flyout's scale on stage: the workspace's, or less so that it takes at most FLYOUT_SHARE of the view. */
  function fittedScale(flyout, scale) {
    const blocks = flyout.getWorkspace().getTopBlocks(false);
    if (!blocks.length) return scale;
    const widest = Math.max(...blocks.map((block) => block.getHeightWidth().width)) + 2 * flyout.MARGIN;
    const view = workspace.getMetricsManager().getViewMetrics().width;
    return Math.max(MIN_FLYOUT_SCALE, Math.min(scale, (FLYOUT_SHARE * view) / widest));
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
  }

  /** Zoom to ``scale`` around the view's top left corner (right of the toolbox), where a program starts (Blockly's setScale
   * zooms around the centre, and the program's start went out of sight). */
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

  return {install, set, active: () => on, MetricsManager: StageMetrics};
})();
