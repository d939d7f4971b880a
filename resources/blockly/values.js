/**
 * Values on the blocks: an expression block's last value, shown on hover in Blockly's own
 * tooltip (Blockly.Tooltip.setCustomTooltip), below the block's usual tooltip text.
 *
 * When values are on, the code Rockly runs hands every expression block's value through
 * `__rockly__.value(ID, value)` (not literals and shadows, whose value is written on them);
 * the window sends the texts back with `show(values)`. Nothing of this reaches a saved
 * program or the exported Python.
 */
'use strict';

const RocklyValues = (() => {
  const LITERALS = new Set(['math_number', 'text', 'logic_boolean', 'logic_null']);
  let values = {};
  let label = 'Last value';

  /** Wrap value blocks' code in `__rockly__.value(ID, (code))` while `generator.rocklyValues` is set. */
  function instrument(generator, Order) {
    const blockToCode = generator.blockToCode;
    generator.blockToCode = function(block, thisOnly) {
      const code = blockToCode.call(this, block, thisOnly);
      if (!this.rocklyValues || !Array.isArray(code) || !code[0] || !block || block.isShadow() ||
          LITERALS.has(block.type)) {
        return code;
      }
      return [`__rockly__.value(${RocklyPython.string(block.id)}, (${code[0]}))`, Order.FUNCTION_CALL];
    };
  }

  function sourceBlock(element) {
    if (element instanceof Blockly.Block) return element;
    return element && typeof element.getSourceBlock === 'function' ? element.getSourceBlock() : null;
  }

  /** Blockly's own tooltip text (wrapped as Blockly wraps it), then the block's last value. */
  function render(div, element) {
    const text = Blockly.utils.string.wrap(Blockly.Tooltip.getTooltipOfObject(element), 50);
    for (const line of text.split('\n')) {
      const row = document.createElement('div');
      row.textContent = line;
      div.appendChild(row);
    }
    const block = sourceBlock(element);
    if (block && Object.prototype.hasOwnProperty.call(values, block.id)) {
      const row = document.createElement('div');
      row.className = 'rocklyValue';
      row.textContent = `${label}: ${values[block.id]}`;
      div.appendChild(row);
    }
  }

  /** Show `shown` ({blockId: text}) on hover from now on ({}: none); `text` names the value. */
  function show(shown, text) {
    values = shown || {};
    if (text) label = text;
  }

  function lastValue(blockId) {
    return Object.prototype.hasOwnProperty.call(values, blockId) ? values[blockId] : null;
  }

  Blockly.Tooltip.setCustomTooltip(render);
  return {instrument, show, lastValue};
})();
