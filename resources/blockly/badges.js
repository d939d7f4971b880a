/**
 * Badges on blocks: what a block's robot commands did in a run or a replay (running,
 * succeeded, aborted, timed out... with the time it took), drawn as a Blockly icon of
 * its own, so Blockly lays it out beside the block's other icons. The icon is not
 * serialisable: it never reaches a saved program, and adding it changes nothing a
 * program holds.
 */
'use strict';

const RocklyBadges = (() => {
  const TYPE = new Blockly.icons.IconType('rockly_badge');
  const HEIGHT = 16;
  const PAD = 6;
  const FONT = '11px sans-serif';  // the badge text's font in rockly.css
  const measure = document.createElement('canvas').getContext('2d');

  /** The width `text` takes in the badge's font (a guess per character cut "running…" short). */
  function textWidth(text) {
    measure.font = FONT;
    return Math.ceil(measure.measureText(text).width);
  }

  class Badge extends Blockly.icons.Icon {
    constructor(block, text, state) {
      super(block);
      this.text = text;
      this.state = state;
    }

    getType() {
      return TYPE;
    }

    getWeight() {
      return 100;  // after Blockly's own icons
    }

    width() {
      return PAD * 2 + textWidth(this.text);
    }

    getSize() {
      return new Blockly.utils.Size(this.width(), HEIGHT);
    }

    isShownWhenCollapsed() {
      return true;
    }

    initView(pointerdownListener) {
      if (this.svgRoot) return;
      super.initView(pointerdownListener);
      this.svgRoot.classList.add('rocklyBadge', 'rocklyBadge-' + this.state);
      Blockly.utils.dom.createSvgElement(Blockly.utils.Svg.RECT,
          {'class': 'rocklyBadgeShape', 'rx': HEIGHT / 2, 'ry': HEIGHT / 2, 'height': HEIGHT, 'width': this.width()},
          this.svgRoot);
      const label = Blockly.utils.dom.createSvgElement(Blockly.utils.Svg.TEXT,
          {'class': 'rocklyBadgeText', 'x': PAD, 'y': HEIGHT - 4}, this.svgRoot);
      label.textContent = this.text;
    }
  }

  /** Show `badges` ({blockId: {text, state}}) and no others. */
  function show(workspace, badges) {
    for (const block of workspace.getAllBlocks(false)) {
      const wanted = badges[block.id];
      const icon = block.getIcon(TYPE);
      const same = icon && wanted && icon.text === wanted.text && icon.state === wanted.state;
      if (icon && !same) block.removeIcon(TYPE);
      if (wanted && !same) block.addIcon(new Badge(block, String(wanted.text), String(wanted.state)));
    }
  }

  return {show};
})();
