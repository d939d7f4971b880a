/**
 * The `rockly_typed_fields` mutator: a ROS block whose type dropdown (message_type,
 * service_type or action_type) lists the types Rockly found, and which grows one checked
 * value input per field of the chosen type (`linear.x`, a Number). The fields are saved
 * with the block and win over the catalog when it opens, so a program opens with all its
 * inputs and their blocks even where its type is unknown or defined differently.
 */
'use strict';

const RocklyTypedFields = (() => {
  const PREFIX = 'field:';
  const CATALOG_OF = {message_type: 'messages', service_type: 'services', action_type: 'actions'};
  let catalog = {messages: {}, services: {}, actions: {}};

  /** Set the types Rockly found: {messages|services|actions: {type: [[path, check], ...]}}. */
  function setCatalog(types) {
    catalog = {messages: {}, services: {}, actions: {}, ...(types || {})};
  }

  const sameFields = (a, b) => JSON.stringify(a) === JSON.stringify(b);
  // What an empty field shows, ready to edit, starting at `start` (lists have no such
  // block: an empty one keeps the type's default).
  const SHADOWS = {
    Number: (start) => ({type: 'math_number', fields: {NUM: Number(start) || 0}}),
    String: (start) => ({type: 'text', fields: {TEXT: typeof start === 'string' ? start : ''}}),
    Boolean: (start) => ({type: 'logic_boolean', fields: {BOOL: start ? 'TRUE' : 'FALSE'}}),
  };

  const mixin = {
    saveExtraState() {
      return {type: this.getFieldValue(this.rocklyTypeField_), fields: this.rocklyFields_};
    },

    loadExtraState(state) {
      const fields = Array.isArray(state && state.fields) ? state.fields : [];
      this.rocklySaved_ = {type: String(state && state.type || ''), fields};
      this.rocklyShowFields_(fields);
    },

    /** The fields of `type`: those it was saved with, else the catalog's. */
    rocklyFieldsOf_(type) {
      if (type === this.rocklySaved_.type) return this.rocklySaved_.fields;
      const known = catalog[CATALOG_OF[this.rocklyTypeField_]] || {};
      return Object.prototype.hasOwnProperty.call(known, type) ? known[type] : [];
    },

    /** Make the field inputs match `fields`; inputs that stay keep their blocks. */
    rocklyShowFields_(fields) {
      fields = fields.filter((entry) => Array.isArray(entry) && typeof entry[0] === 'string')
          .map(([path, check, start]) =>
            [path, ['Number', 'String', 'Boolean', 'Array'].includes(check) ? check : null, start ?? null]);
      if (sameFields(fields, this.rocklyFields_)) return;
      const wanted = new Map(fields.map(([path, check]) => [PREFIX + path, check]));
      const starts = new Map(fields.map(([path, , start]) => [PREFIX + path, start]));
      for (const input of [...this.inputList]) {
        if (!input.name.startsWith(PREFIX)) continue;
        const check = (input.connection.getCheck() || [null])[0];
        if (wanted.has(input.name) && wanted.get(input.name) === check) continue;
        const child = input.connection.targetBlock();
        if (child && !child.isShadow()) child.unplug();  // moved aside, not deleted
        this.removeInput(input.name);
      }
      // The field inputs follow the input that holds the type dropdown, in the type's order.
      let position = this.inputList.indexOf(this.getField(this.rocklyTypeField_).getParentInput()) + 1;
      for (const [name, check] of wanted) {
        if (!this.getInput(name)) {
          const input = this.appendValueInput(name).setCheck(check).setAlign(Blockly.inputs.Align.RIGHT)
              .appendField(name.slice(PREFIX.length));
          if (SHADOWS[check]) input.connection.setShadowState(SHADOWS[check](starts.get(name)));
        }
        const current = this.inputList.indexOf(this.getInput(name));
        if (current !== position) this.moveNumberedInputBefore(current, position);
        position++;
      }
      this.rocklyFields_ = fields;
    },

    /** The Python dict of the filled-in fields, nested by path: {'linear': {'x': 0.1}}. */
    rocklyFieldsCode(generator) {
      const tree = {};
      for (const input of this.inputList) {
        if (!input.name.startsWith(PREFIX)) continue;
        const code = generator.valueToCode(this, input.name, python.Order.NONE);
        if (!code) continue;
        const parts = input.name.slice(PREFIX.length).split('.');
        let node = tree;
        for (const part of parts.slice(0, -1)) node = node[part] = node[part] || {};
        node[parts[parts.length - 1]] = code;
      }
      const render = (node) => '{' + Object.entries(node).map(([key, value]) =>
        RocklyPython.string(key) + ': ' + (typeof value === 'string' ? value : render(value))).join(', ') + '}';
      return render(tree);
    },
  };

  /** Replace the block's static type dropdown with one over the catalog's types. */
  function setUp() {
    this.rocklyTypeField_ = Object.keys(CATALOG_OF).find((name) => this.getField(name));
    this.rocklyFields_ = [];
    this.rocklySaved_ = {type: '', fields: []};
    const original = this.getField(this.rocklyTypeField_);
    const input = original.getParentInput();
    const position = input.fieldRow.indexOf(original);
    const initial = original.getValue();
    input.removeField(this.rocklyTypeField_);
    const options = () => {
      const names = Object.keys(catalog[CATALOG_OF[this.rocklyTypeField_]] || {});
      for (const extra of [initial, this.rocklySaved_.type]) if (extra && !names.includes(extra)) names.push(extra);
      return names.sort().map((name) => [name, name]);
    };
    const dropdown = new Blockly.FieldDropdown(options, (type) => {
      this.rocklyShowFields_(this.rocklyFieldsOf_(type));
      return type;
    });
    input.insertFieldAt(position, dropdown, this.rocklyTypeField_);
    dropdown.setValue(initial);
    this.rocklyShowFields_(this.rocklyFieldsOf_(initial));
  }

  Blockly.Extensions.registerMutator('rockly_typed_fields', mixin, setUp);

  return {setCatalog, PREFIX};
})();
