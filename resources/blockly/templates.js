/**
 * Turns a profile's Python templates (declared as data in its block file) into Blockly
 * generators: fields become quoted literals, value inputs sub-expressions, statement
 * inputs indented bodies (or, for handlers, functions defined before the program), and a
 * typed-fields block's `{fields}` the dict of its field inputs.
 */
'use strict';

const RocklyTemplates = (() => {
  const PLACEHOLDER = /\{\{|\}\}|\{(\w+)\}/g;

  /** True when the template is one call, e.g. `robot.ask({text})`, so it binds tightly. */
  function isSingleCall(code) {
    const trimmed = code.trim();
    const open = trimmed.search(/^[\w.]+\(/) === 0 ? trimmed.indexOf('(') : -1;
    if (open < 0 || !trimmed.endsWith(')')) return false;
    let depth = 0;
    for (let i = open; i < trimmed.length; i++) {
      if (trimmed[i] === '(') depth++;
      if (trimmed[i] === ')') depth--;
      if (depth === 0) return i === trimmed.length - 1;
    }
    return false;
  }

  /** The Python literal for a field's value: mapped through `values`, typed by the field. */
  function fieldLiteral(block, name, spec) {
    const field = block.getField(name);
    const value = field.getValue();
    const mapping = spec.values[name];
    if (mapping && Object.prototype.hasOwnProperty.call(mapping, value)) {
      return RocklyPython.literal(mapping[value]);
    }
    if (field instanceof Blockly.FieldNumber) return RocklyPython.literal(Number(value));
    if (field instanceof Blockly.FieldCheckbox) return value === 'TRUE' ? 'True' : 'False';
    if (field instanceof Blockly.FieldVariable) return python.pythonGenerator.getVariableName(value);
    return RocklyPython.string(value);
  }

  /**
   * A handler: the statement input as a function of one argument, defined before the
   * program; the argument goes into the block's variable field. 'None' when it is empty.
   */
  function handlerFunction(block, generator, input, variableField) {
    const body = generator.statementToCode(block, input);
    if (!body) return 'None';
    const names = generator.nameDB_;
    const name = names.getDistinctName(input, Blockly.Names.NameType.PROCEDURE);
    const argument = names.getDistinctName('received', Blockly.Names.NameType.VARIABLE);
    const globals = Blockly.Variables.allUsedVarModels(block.workspace)
        .map((variable) => generator.getVariableName(variable.getId()));
    const target = generator.getVariableName(block.getFieldValue(variableField));
    generator.definitions_['%handler_' + name] =
        'def ' + name + '(' + argument + '):\n' +
        (globals.length ? generator.INDENT + 'global ' + globals.join(', ') + '\n' : '') +
        generator.INDENT + target + ' = ' + argument + '\n' + body;
    return name;
  }

  /** A Blockly generator function for one templated block. */
  function makeGenerator(spec) {
    const order = python.Order;
    const bindsTightly = isSingleCall(spec.code);
    return (block, generator) => {
      const code = spec.code.replace(PLACEHOLDER, (match, name) => {
        if (match === '{{') return '{';
        if (match === '}}') return '}';
        const slot = spec.slots[name];
        if (slot === 'field') return fieldLiteral(block, name, spec);
        if (slot === 'typed_fields') return block.rocklyFieldsCode(generator);
        if (slot === 'statement' && spec.handlers[name]) {
          return handlerFunction(block, generator, name, spec.handlers[name]);
        }
        if (slot === 'statement') {
          return generator.statementToCode(block, name) || generator.INDENT + 'pass\n';
        }
        const value = generator.valueToCode(block, name, order.NONE);
        if (value) return value;
        return name in spec.defaults ? RocklyPython.literal(spec.defaults[name]) : 'None';
      });
      if (spec.expression) return [code, bindsTightly ? order.FUNCTION_CALL : order.NONE];
      return code.endsWith('\n') ? code : code + '\n';
    };
  }

  /** Define the profile's blocks and their generators. */
  function install(blocks) {
    Blockly.common.defineBlocksWithJsonArray(blocks.map((block) => block.definition));
    for (const block of blocks) {
      python.pythonGenerator.forBlock[block.definition.type] = makeGenerator(block.python);
    }
  }

  return {install, isSingleCall};
})();
