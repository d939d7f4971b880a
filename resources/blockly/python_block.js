/**
 * The Python block: Python that no other block says, kept verbatim when Python is turned back into blocks
 * (rockly_desktop/python_blocks). It shows its text as code, one line a row; its generator writes the text
 * as it is, so it runs as one statement and is stepped as one step (the statement prefix comes before it).
 * Its commands go through the same `robot` and `ros` as every block's: the teacher's limits hold below it.
 */
'use strict';

const RocklyPythonBlock = (() => {
  const TYPE = 'rockly_python';

  const mixin = {
    saveExtraState() {
      return {code: this.rocklyCode_};
    },

    loadExtraState(state) {
      this.rocklySetCode_(String((state && state.code) || ''));
    },

    /** Show `code` one line a row, in the code font. */
    rocklySetCode_(code) {
      this.rocklyCode_ = code;
      for (const input of [...this.inputList]) this.removeInput(input.name);
      code.split('\n').forEach((line, index) => {
        const label = new Blockly.FieldLabel(line.replace(/\t/g, '    ') || ' ', 'rocklyPythonCode');
        this.appendDummyInput('LINE' + index).appendField(label);
      });
    },
  };

  Blockly.Blocks[TYPE] = {
    init() {
      this.rocklyCode_ = '';
      this.setPreviousStatement(true);
      this.setNextStatement(true);
      this.setColour('#4b5563');
      this.setTooltip(() => (Blockly.Msg.ROCKLY_PYTHON_BLOCK_TOOLTIP || 'Python'));
      this.rocklySetCode_('');
    },
    ...mixin,
  };

  python.pythonGenerator.forBlock[TYPE] = (block) => block.rocklyCode_ + '\n';

  return {TYPE};
})();
