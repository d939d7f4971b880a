/**
 * The editor page: Blockly plus one narrow JSON channel to Rockly's Python side.
 *
 * Python -> page: {call, id, args} on the bridge's `toPage` signal.
 * Page -> Python: {reply: id, result | error}, or {event: 'hello' | 'changed' | 'error', ...}
 * through the bridge's `fromPage` slot. Python queues its calls until `setup` has run;
 * `setup` may carry a first call (the program to open at start) so it shows in one go, and
 * may build the workspace `hidden` ahead of the window, which then shows it with `show`;
 * the first call's answer comes back as `program: {result | error}`.
 * A program with block types the page does not know is refused with `unknownTypes`, one
 * with a block without a type with `untypedBlock` (its number); a program that loads
 * answers with `replacedFields` when Blockly could not keep some of its field values.
 */
'use strict';

(() => {
  let bridge = null;
  let workspace = null;
  let loading = false;
  let changeTimer = null;
  let errorBlockId = null;  // the block marked with the last run's error, until it is edited
  const CHANGE_DEBOUNCE_MS = 60;

  function send(message) {
    bridge.fromPage(JSON.stringify(message));
  }

  window.addEventListener('error', (event) => {
    if (bridge) send({event: 'error', message: String(event.message), source: event.filename, line: event.lineno});
  });

  // Rockly plays no sounds (`sounds: false`), yet every Blockly workspace makes an AudioContext when
  // the browser offers one, and starting Chromium's audio for it took most of the inject's time (74 of
  // 113 ms in a profile, longer while Rockly's Python was busy). Without it Blockly stays silent.
  delete window.AudioContext;

  // Rockly writes every string as a Python literal that keeps newlines and quotes exactly.
  python.pythonGenerator.quote_ = RocklyPython.string;
  python.pythonGenerator.multiline_quote_ = RocklyPython.string;
  // Comments are written as "# ..." lines. Python also ends a line at a lone carriage
  // return, so a comment holding one could start a line of code: every line break Python
  // knows becomes "\n" (and so gets its own "# "), and NUL, which Python refuses, goes.
  const prefixLines = python.pythonGenerator.prefixLines.bind(python.pythonGenerator);
  python.pythonGenerator.prefixLines = (text, prefix) =>
    prefixLines(String(text).replace(/\r\n?|[\u2028\u2029]/g, '\n').replace(/\0/g, ''), prefix);
  // Block ids go into the instrumented code too; Blockly pastes them between quotes
  // unescaped, so an id from a crafted file could become code. Quote them properly.
  python.pythonGenerator.injectId = (message, block) =>
    message.replace(/%1/g, () => RocklyPython.string(block.id));
  // The names a run binds for the program: a variable or function of the same name
  // ("robot = 5") would replace them, so Blockly renames those ("robot2"), as it does
  // for Python's keywords.
  python.pythonGenerator.addReservedWords('robot,ros,__rockly__');
  guardLargeResults(python.pythonGenerator, python.Order);
  RocklyValues.instrument(python.pythonGenerator, python.Order);
  RocklyKeyboardPlacing.install();

  function loadScript(src) {
    return new Promise((resolve, reject) => {
      const script = document.createElement('script');
      script.src = src;
      script.onload = resolve;
      script.onerror = () => reject(new Error('cannot load ' + src));
      document.head.appendChild(script);
    });
  }

  function state() {
    return {
      workspace: Blockly.serialization.workspaces.save(workspace),
      python: python.pythonGenerator.workspaceToCode(workspace),
    };
  }

  /** Send the workspace and its Python to Rockly; returns what was sent. */
  function reportChange(origin) {
    clearTimeout(changeTimer);
    changeTimer = null;
    const current = state();
    send({event: 'changed', origin, ...current});
    return current;
  }

  // --- loose value blocks, the empty canvas's hint, where a program opens --------------

  /**
   * A value block lying loose on the canvas has nowhere to give its value: it is not run
   * (nor exported) and looks disabled, with the reason Blockly's own orphans get. Loose
   * statement stacks still run (first-Rockly programs depend on that), which is why
   * Blockly's `disableOrphans`, which disables those too, is not used.
   */
  const LOOSE = 'ORPHANED_BLOCK';

  function markLooseValues() {
    const recordUndo = Blockly.Events.getRecordUndo();
    Blockly.Events.setRecordUndo(false);  // follows the move that caused it, as Blockly's orphans do
    try {
      for (const block of workspace.getAllBlocks(false)) {
        const loose = Boolean(block.outputConnection) && !block.getParent();
        if (block.hasDisabledReason(LOOSE) !== loose) block.setDisabledReason(loose, LOOSE);
      }
    } finally {
      Blockly.Events.setRecordUndo(recordUndo);
    }
  }

  const PLACING_EVENTS = new Set([Blockly.Events.BLOCK_CREATE, Blockly.Events.BLOCK_MOVE, Blockly.Events.BLOCK_DRAG,
                                  Blockly.Events.BLOCK_DELETE]);

  function afterPlacing(event) {
    if (event.type === Blockly.Events.TOOLBOX_ITEM_SELECT) updateHint();
    if (!PLACING_EVENTS.has(event.type) || workspace.isDragging()) return;
    markLooseValues();
    updateHint();
  }

  let hint = null;

  /** The empty canvas's hint, drawn over the workspace's background; hidden while a category's blocks are out. */
  function makeHint(text) {
    if (!text) return;
    hint = document.createElement('div');
    hint.id = 'emptyHint';
    hint.textContent = text;
    const svg = workspace.getParentSvg();
    svg.parentNode.insertBefore(hint, svg.nextSibling);
    updateHint();
  }

  function updateHint() {
    if (!hint) return;
    const flyout = workspace.getFlyout();
    hint.hidden = workspace.getTopBlocks(false).length > 0 || Boolean(flyout && flyout.isVisible());
    hint.style.left = workspace.getMetricsManager().getAbsoluteMetrics().left + 'px';
  }

  const START_MARGIN = 24;  // pixels between the view's corner and the program's

  // Blockly keeps the view's centre when the editor is resized (a dock shown, the stage view),
  // which slides the program's start off the left edge. Rockly keeps the view's top-left
  // corner instead, and a view still showing the program's start (the person has not moved
  // it since it opened) shows the start again: a program opened before the page had its
  // final size may not have been scrolled all the way there.
  let viewCorner = null;  // the view's top-left corner in workspace units, as last seen
  let startCorner = null;  // where showProgramStart put it

  function noteViewCorner() {
    const view = workspace.getMetricsManager().getViewMetrics(true);
    viewCorner = {left: view.left, top: view.top};
  }

  function sameCorner(a, b) {
    return Boolean(a && b) && Math.abs(a.left - b.left) < 1 && Math.abs(a.top - b.top) < 1;
  }

  /** Scroll so that the program's top-left corner is near the view's: a program opens at its start. */
  function showProgramStart() {
    if (!workspace.getTopBlocks(false).length) {
      workspace.scrollCenter();
    } else {
      const box = workspace.getBlocksBoundingBox();
      const scale = workspace.scale;
      workspace.scroll(START_MARGIN - box.left * scale, START_MARGIN - box.top * scale);
    }
    noteViewCorner();  // no viewport event comes while a load has events off
    startCorner = viewCorner;
  }

  /** After Blockly's own resize handler (window 'resize', bound at inject): the corner as before. */
  function keepViewCorner() {
    if (sameCorner(viewCorner, startCorner)) {
      showProgramStart();
    } else if (viewCorner) {
      workspace.scroll(-viewCorner.left * workspace.scale, -viewCorner.top * workspace.scale);
    }
  }

  function onWorkspaceEvent(event) {
    if (event.type === Blockly.Events.VIEWPORT_CHANGE) noteViewCorner();
    if (loading || event.isUiEvent) return;
    if (errorBlockId && event.blockId === errorBlockId && event.type !== Blockly.Events.BLOCK_MOVE) {
      clearError();  // the child changed the block the error came from: the mark has done its job
    }
    clearTimeout(changeTimer);
    changeTimer = setTimeout(() => reportChange('user'), CHANGE_DEBOUNCE_MS);
  }

  /**
   * Replace the workspace without the load counting as a user's edit. Returns the
   * workspace as it was reported (the one serialization a load needs).
   */
  function replaceWorkspace(fill) {
    loading = true;
    Blockly.Events.disable();
    try {
      workspace.clear();
      breakpoints.clear();
      fill();
      markLooseValues();
    } finally {
      Blockly.Events.enable();
      loading = false;
    }
    workspace.clearUndo();
    showProgramStart();
    updateHint();
    return reportChange('load').workspace;
  }

  /** Like replaceWorkspace, but a program that fails to load leaves the old one (and its breakpoints) in place. */
  function replaceOrRestore(fill) {
    const previous = Blockly.serialization.workspaces.save(workspace);
    const previousBreakpoints = [...breakpoints];
    try {
      return replaceWorkspace(fill);
    } catch (error) {
      replaceWorkspace(() => Blockly.serialization.workspaces.load(previous, workspace));
      setBreakpoints(previousBreakpoints);
      throw error;
    }
  }

  // --- running: instrumented code, the current block, breakpoints, errors -------------

  const breakpoints = new Set();

  function markBreakpoint(id, on) {
    const block = workspace.getBlockById(id);
    const root = block && block.getSvgRoot && block.getSvgRoot();
    if (root) root.classList.toggle('rocklyBreakpoint', on);
  }

  function setBreakpoints(ids) {
    for (const id of breakpoints) markBreakpoint(id, false);
    breakpoints.clear();
    for (const id of ids || []) {
      if (workspace.getBlockById(id)) {
        breakpoints.add(id);
        markBreakpoint(id, true);
      }
    }
  }

  function toggleBreakpoint(id) {
    const ids = new Set(breakpoints);
    if (ids.has(id)) ids.delete(id); else ids.add(id);
    setBreakpoints([...ids]);
    send({event: 'breakpoints', ids: [...breakpoints]});
  }

  function registerContextMenu(texts, madeBlocks) {
    const registry = Blockly.ContextMenuRegistry.registry;
    if (registry.getItem('rocklyEditMadeBlock')) registry.unregister('rocklyEditMadeBlock');
    const made = new Set(madeBlocks || []);
    registry.register({  // a block made with the block maker opens in it again
      id: 'rocklyEditMadeBlock',
      scopeType: Blockly.ContextMenuRegistry.ScopeType.BLOCK,
      weight: 1,
      displayText: () => texts.editMadeBlock || 'Edit this block…',
      preconditionFn: (scope) => made.has(scope.block.type) ? 'enabled' : 'hidden',
      callback: (scope) => send({event: 'editMadeBlock', type: scope.block.type}),
    });
    if (registry.getItem('rocklyBreakpoint')) registry.unregister('rocklyBreakpoint');
    registry.register({
      id: 'rocklyBreakpoint',
      scopeType: Blockly.ContextMenuRegistry.ScopeType.BLOCK,
      weight: 0,
      displayText: (scope) => breakpoints.has(scope.block.id) ? texts.removeBreakpoint : texts.addBreakpoint,
      preconditionFn: (scope) => scope.block.previousConnection || scope.block.nextConnection ? 'enabled' : 'hidden',
      callback: (scope) => toggleBreakpoint(scope.block.id),
    });
  }

  /**
   * In the code Rockly runs, powers, products and repeated lists go through `__rockly__`,
   * which refuses results too large to compute in a blink: one `9 ** 999999999` would hold
   * Python for minutes, where no STOP can reach it. Exported Python keeps the operators.
   */
  function guardLargeResults(generator, Order) {
    const arithmetic = generator.forBlock['math_arithmetic'];
    generator.forBlock['math_arithmetic'] = function(block, gen) {
      const guard = {POWER: 'power', MULTIPLY: 'times'}[block.getFieldValue('OP')];
      if (!gen.rocklyGuarded || !guard) return arithmetic.call(this, block, gen);
      const a = gen.valueToCode(block, 'A', Order.NONE) || '0';
      const b = gen.valueToCode(block, 'B', Order.NONE) || '0';
      return [`__rockly__.${guard}(${a}, ${b})`, Order.FUNCTION_CALL];
    };
    const repeat = generator.forBlock['lists_repeat'];
    generator.forBlock['lists_repeat'] = function(block, gen) {
      if (!gen.rocklyGuarded) return repeat.call(this, block, gen);
      const item = gen.valueToCode(block, 'ITEM', Order.NONE) || 'None';
      const count = gen.valueToCode(block, 'NUM', Order.NONE) || '0';
      return [`__rockly__.times([${item}], ${count})`, Order.FUNCTION_CALL];
    };
  }

  /**
   * The program as it runs: a hook before every statement and in every loop, and its variables;
   * with `values`, every expression block's value also passes `__rockly__.value`.
   */
  function runCode(values) {
    const generator = python.pythonGenerator;
    generator.rocklyGuarded = true;
    generator.rocklyValues = Boolean(values);
    generator.STATEMENT_PREFIX = '__rockly__.block(%1)\n';
    generator.INFINITE_LOOP_TRAP = '__rockly__.check()\n';
    try {
      // The generator names variables while it runs; ask it the same way it will be asked.
      generator.init(workspace);
      const variables = {};
      for (const variable of workspace.getVariableMap().getAllVariables()) {
        variables[variable.getName()] = generator.getVariableName(variable.getId());
      }
      generator.finish('');
      const code = generator.workspaceToCode(workspace);
      return {code, variables, breakpoints: [...breakpoints]};
    } finally {
      generator.rocklyGuarded = false;
      generator.rocklyValues = false;
      generator.STATEMENT_PREFIX = null;
      generator.INFINITE_LOOP_TRAP = null;
    }
  }

  function clearMarks() {
    workspace.highlightBlock(null);
    errorBlockId = null;
    for (const block of workspace.getAllBlocks(false)) {
      if (block.getSvgRoot) block.getSvgRoot().classList.remove('rocklyError');
      block.setWarningText(null);
    }
  }

  function clearError() {
    const block = workspace.getBlockById(errorBlockId);
    errorBlockId = null;
    if (!block) return;
    block.getSvgRoot().classList.remove('rocklyError');
    block.setWarningText(null);
  }

  /** Block types in a program (Blockly JSON or XML) that this page cannot create. */
  function unknownTypes(types) {
    return [...new Set(types)].filter((type) => !Blockly.Blocks[type]).sort();
  }

  /**
   * The blocks of a Blockly JSON program in the order the file's text has them: a block,
   * then what its inputs and `next` hold, as written (core/workspace_blocks.py counts the
   * same way), so that "block 3" is the third block a person finds in the file.
   */
  function blocksInFileOrder(json) {
    const ordered = [];
    const top = json && typeof json.blocks === 'object' && json.blocks ? json.blocks.blocks : null;
    const pending = Array.isArray(top) ? [...top].reverse() : [];
    while (pending.length) {
      const block = pending.pop();
      if (!block || typeof block !== 'object' || Array.isArray(block)) continue;
      ordered.push(block);
      const children = [];
      for (const connection of jsonConnections(block)) {
        for (const [kind, child] of Object.entries(connection)) {
          if ((kind === 'block' || kind === 'shadow') && child) children.push(child);
        }
      }
      pending.push(...children.reverse());
    }
    return ordered;
  }

  /** A JSON block's connections as written: [{input (null for next), block, shadow}]. */
  function jsonConnections(block) {
    const connections = [];
    for (const [key, value] of Object.entries(block)) {
      const isObject = (item) => item && typeof item === 'object' && !Array.isArray(item);
      if (key === 'inputs' && isObject(value)) {
        for (const [input, connection] of Object.entries(value)) {
          if (isObject(connection)) connections.push({...connection, input});
        }
      } else if (key === 'next' && isObject(value)) {
        connections.push({...value, input: null});
      }
    }
    return connections;
  }

  const JSON_PROGRAM = {
    fields: (block) => (block.fields && typeof block.fields === 'object' ? Object.entries(block.fields) : []),
    connections: jsonConnections,
  };

  function xmlChildren(element, ...names) {
    return [...element.children].filter((child) => names.includes(child.nodeName.toLowerCase()));
  }

  const XML_PROGRAM = {
    fields: (element) => xmlChildren(element, 'field').map((field) => [field.getAttribute('name'), field.textContent]),
    connections: (element) => xmlChildren(element, 'value', 'statement', 'next').map((connection) => ({
      input: connection.nodeName.toLowerCase() === 'next' ? null : connection.getAttribute('name'),
      block: xmlChildren(connection, 'block')[0],
      shadow: xmlChildren(connection, 'shadow')[0],
    })),
  };

  /** Whether a field now holds the value the file asked for (numbers and booleans as Blockly stores them). */
  function sameValue(wanted, now) {
    if (wanted === now) return true;
    if (wanted === null || now === null || typeof wanted === 'object' || typeof now === 'object') return false;
    if (typeof wanted === 'boolean' || typeof now === 'boolean') {
      return String(wanted).toUpperCase() === String(now).toUpperCase();
    }
    if (typeof wanted === 'number' || typeof now === 'number') {
      return String(wanted).trim() !== '' && String(now).trim() !== '' && Number(wanted) === Number(now);
    }
    return String(wanted) === String(now);
  }

  /**
   * The field values a just-loaded program asked for that its blocks do not hold: a
   * dropdown choice the block does not offer, a number outside its range, a field the
   * block does not have. Blockly replaces or drops those silently; Rockly says so.
   * `pairs` are [block as in the file, the same block as Blockly now saves it] (a shadow
   * covered by a block included: Blockly keeps its state, checked too); `numbers` maps
   * the former to its number in the file.
   */
  function fieldsNotKept(program, pairs, numbers) {
    const replaced = [];
    pairs = [...pairs];
    while (pairs.length) {
      const [wanted, saved] = pairs.pop();
      if (!wanted || !saved) continue;
      const savedFields = saved.fields || {};
      const block = workspace.getBlockById(saved.id);
      for (const [name, value] of program.fields(wanted)) {
        if (Object.prototype.hasOwnProperty.call(savedFields, name)) {
          const now = savedFields[name];
          // A variable field ({id}) makes the variable it names: nothing is replaced.
          if ((now && typeof now === 'object') || sameValue(value, now)) continue;
          replaced.push({number: numbers.get(wanted), id: saved.id, type: saved.type, field: name, requested: value, now});
        } else if (!(block && block.getField(name))) {  // a field that is not saved (a label) is no loss
          replaced.push({number: numbers.get(wanted), id: saved.id, type: saved.type, field: name, requested: value,
                         missing: true});
        }
      }
      const savedConnections = {...(saved.inputs || {}), [NEXT]: saved.next};
      for (const {input, block: child, shadow} of program.connections(wanted)) {
        const connection = savedConnections[input === null ? NEXT : input];
        if (!connection) continue;
        if (child) pairs.push([child, connection.block]);
        if (shadow) pairs.push([shadow, connection.shadow]);
      }
    }
    return replaced.sort((a, b) => a.number - b.number);
  }

  const NEXT = Symbol('next');

  /**
   * The blocks at the top of `saved` (the workspace as Blockly saved it), in the order
   * Blockly created them, each with everything it holds.
   */
  function topBlocksOf(saved) {
    return (saved.blocks || {}).blocks || [];
  }

  /** The answer's `replacedFields` part: absent when every value was kept. */
  function replacedFields(replaced) {
    return replaced.length ? {replacedFields: replaced} : {};
  }

  // --- how the blocks look: high contrast, larger text (Preferences) --------------------

  const themes = new Map();

  /** A Blockly theme for `look`: Zelos' own with larger bold text and/or black-and-white surroundings. */
  function lookTheme(look) {
    const name = `rockly${look.highContrast ? '-contrast' : ''}${look.largeText ? '-large' : ''}`;
    if (!themes.has(name)) {
      themes.set(name, Blockly.Theme.defineTheme(name, {
        base: Blockly.Themes.Classic,
        fontStyle: look.largeText ? {size: 17, weight: 'bold'} : {},
        componentStyles: look.highContrast ? {
          workspaceBackgroundColour: '#ffffff', toolboxBackgroundColour: '#000000',
          toolboxForegroundColour: '#ffffff', flyoutBackgroundColour: '#202020', flyoutForegroundColour: '#ffffff',
          flyoutOpacity: 1, scrollbarColour: '#000000', scrollbarOpacity: 1, insertionMarkerColour: '#000000',
          insertionMarkerOpacity: 0.5, cursorColour: '#d50000', selectedGlowColour: '#ffd600',
        } : {},
      }));
    }
    return themes.get(name);
  }

  /** The page's classes for ``look``; returns its theme. Block colours are the profile's own: high contrast darkens
   * them under white text and black outlines (rockly.css). */
  function lookClasses(look) {
    look = look || {};
    document.getElementById('workspace').classList.toggle('rocklyHighContrast', Boolean(look.highContrast));
    document.getElementById('workspace').classList.toggle('rocklyLargeText', Boolean(look.largeText));
    return lookTheme(look);
  }

  /** Show the blocks in another look (the setup gave the first). */
  function setLook(look) {
    workspace.setTheme(lookClasses(look));
    // Fields keep the size they measured in the old font: measure every one again, then the toolbox's
    // new width takes its room from the workspace, whose view keeps its corner.
    for (const block of workspace.getAllBlocks(false)) {
      for (const input of block.inputList) for (const field of input.fieldRow) field.forceRerender();
    }
    workspace.render();
    Blockly.svgResize(workspace);
    keepViewCorner();
    return {theme: workspace.getTheme().name};
  }

  const calls = {
    async setup({language, profile, media, first, texts, hidden, look}) {
      if (language !== 'en') await loadScript('vendor/msg/' + language + '.js');
      Object.assign(Blockly.Msg, (texts && texts.blocklyMsg) || {});  // Blockly's hints and untranslated words, in Rockly's
      RocklyNumbers.setLanguage(language, texts && texts.numberRefused);
      // Prepared ahead of the program: nothing shows until `show`.
      if (hidden) document.getElementById('workspace').style.visibility = 'hidden';
      RocklyTypedFields.setCatalog(profile.types);
      RocklyTemplates.install(profile.blocks);
      workspace = Blockly.inject('workspace', {
        toolbox: profile.toolbox,
        media,
        renderer: 'zelos',
        theme: lookClasses(look),  // the look from the start: setting it later measures every block again
        grid: {spacing: 24, length: 3, colour: '#dfe3ea', snap: true},
        zoom: {controls: true, wheel: true, startScale: 0.8, maxScale: 2.5, minScale: 0.3, scaleSpeed: 1.15},
        trashcan: true,
        move: {scrollbars: true, drag: true, wheel: false},
        sounds: false,
        plugins: {metricsManager: RocklyStage.MetricsManager},
      });
      workspace.addChangeListener(onWorkspaceEvent);
      RocklyKeyNames.watch();
      workspace.addChangeListener(afterPlacing);
      RocklyLessonMarks.watch(workspace);
      RocklyStage.install(workspace);
      window.addEventListener('resize', keepViewCorner);  // added after inject's own: runs after it
      makeHint(texts && texts.emptyHint);
      registerContextMenu(texts || {addBreakpoint: 'Add breakpoint', removeBreakpoint: 'Remove breakpoint'},
                          profile.madeBlocks);
      // The first call's own answer, or its error: a program that cannot be shown must not stop the editor.
      let program = null;
      if (first) {
        try {
          program = {result: calls[first.call](first.args)};
        } catch (error) {
          program = {error: String(error && error.message || error)};
        }
      }
      return {blockTypes: Object.keys(Blockly.Blocks), program};
    },
    load({workspace: json, breakpoints: ids}) {
      const blocks = blocksInFileOrder(json);
      const untyped = blocks.findIndex((block) => typeof block.type !== 'string' || !block.type);
      if (untyped >= 0) return {untypedBlock: untyped + 1};
      const unknown = unknownTypes(blocks.map((block) => block.type));
      if (unknown.length) return {unknownTypes: unknown};
      const saved = replaceOrRestore(() => Blockly.serialization.workspaces.load(json, workspace));
      setBreakpoints(ids);
      // Blockly creates the top blocks in the file's order; pair each with its state.
      const tops = (json.blocks || {}).blocks || [];
      const pairs = topBlocksOf(saved).map((state, index) => [tops[index], state]);
      const numbers = new Map(blocks.map((block, index) => [block, index + 1]));
      return {loaded: true, ...replacedFields(fieldsNotKept(JSON_PROGRAM, pairs, numbers))};
    },
    importXml({xml}) {
      const dom = Blockly.utils.xml.textToDom(xml);
      const elements = [...dom.querySelectorAll('block, shadow')];
      const untyped = elements.findIndex((element) => !element.getAttribute('type'));
      if (untyped >= 0) return {untypedBlock: untyped + 1};
      const unknown = unknownTypes(elements.map((element) => element.getAttribute('type')));
      if (unknown.length) return {unknownTypes: unknown};
      let topIds = [];
      const saved = replaceOrRestore(() => { topIds = Blockly.Xml.domToWorkspace(dom, workspace); });
      const blocksAtTop = xmlChildren(dom, 'block');
      const tops = blocksAtTop.length === topIds.length ? blocksAtTop : xmlChildren(dom, 'block', 'shadow');
      const savedById = new Map(topBlocksOf(saved).map((state) => [state.id, state]));
      const pairs = topIds.map((id, index) => [tops[index], savedById.get(id)]);
      const numbers = new Map(elements.map((element, index) => [element, index + 1]));
      return {loaded: true, ...replacedFields(fieldsNotKept(XML_PROGRAM, pairs, numbers))};
    },
    /**
     * The block maker's preview: define ``block`` (an editor_config entry) anew and show it alone, as
     * ``state`` (its toolbox entry, with its inputs' defaults) says; no zoom buttons, no trash can.
     */
    preview({block, state}) {
      RocklyTemplates.install([block]);
      document.body.classList.add('rocklyPreview');
      replaceWorkspace(() => Blockly.serialization.blocks.append({...state, x: 16, y: 16}, workspace));
      return true;
    },
    setToolbox({toolbox}) {
      workspace.updateToolbox(toolbox);
      RocklyLessonMarks.refresh(workspace);
      return true;
    },
    clear() {
      replaceWorkspace(() => {});
      return true;
    },
    show() {
      document.getElementById('workspace').style.visibility = '';
      return true;
    },
    getState() {
      return state();
    },
    getRunCode({values}) {
      return runCode(values);
    },
    highlight({id}) {
      workspace.highlightBlock(id || null);
      const block = id && workspace.getBlockById(id);
      if (block) workspace.scrollBoundsIntoView(block.getBoundingRectangleWithoutChildren());
      return true;
    },
    /** A lesson step's blocks marked in the toolbox, its flyout and on the canvas ([]: none); the types marked. */
    markLessonBlocks({types}) {
      return RocklyLessonMarks.set(workspace, types);
    },
    setBreakpoints({ids}) {
      setBreakpoints(ids);
      return [...breakpoints];
    },
    async markError({id, message}) {
      clearMarks();
      const block = id && workspace.getBlockById(id);
      if (!block) return false;
      block.getSvgRoot().classList.add('rocklyError');
      block.setWarningText(message);
      errorBlockId = id;
      await Blockly.renderManagement.finishQueuedRenders();  // its warning icon drawn: the block as wide as it shows
      // Not selected: a selected block is outlined in the running glow's yellow, and the
      // error must look like an error (rockly.css keeps it red should it be selected later).
      workspace.centerOnBlock(id);
      noteViewCorner();  // now, not when the viewport event comes: a resize before it (the replay bar) keeps the block
      const box = block.getSvgRoot().getBoundingClientRect();
      return {left: box.left, top: box.top, width: box.width, height: box.height};  // where the message goes beside
    },
    clearMarks() {
      clearMarks();
      RocklyBadges.show(workspace, {});
      RocklyValues.show({});
      return true;
    },
    setValues({values, label}) {
      RocklyValues.show(values || {}, label);
      return true;
    },
    setStage({on}) {
      RocklyStage.set(Boolean(on));
      return true;
    },
    setBadges({badges}) {
      RocklyBadges.show(workspace, badges || {});
      return true;
    },
    /** The keyboard enters the page: on the workspace (its last focused block), Blockly's keys on. */
    focusWorkspace() {
      Blockly.keyboardNavigationController.setIsActive(true);
      Blockly.getFocusManager().focusTree(workspace);
      return true;
    },
    /** The keyboard goes to the toolbox (Blockly's T key, from outside the page). */
    focusToolbox() {
      Blockly.keyboardNavigationController.setIsActive(true);
      Blockly.getFocusManager().focusTree(workspace.getToolbox() || workspace.getFlyout().getWorkspace());
      return true;
    },
    setLook(look) {
      return setLook(look);
    },
    undo() {
      workspace.undo(false);
      return true;
    },
    redo() {
      workspace.undo(true);
      return true;
    },
  };

  async function runCall(text) {
    const {call, id, args} = JSON.parse(text);
    try {
      if (!calls[call]) throw new Error('unknown call ' + call);
      const result = await calls[call](args || {});
      send({reply: id, result});
    } catch (error) {
      send({reply: id, error: String(error && error.message || error)});
    }
  }

  // Calls run one after another, in the order sent, even while one waits (setup loading a
  // language): Python sends the start-up program right behind the setup, unanswered yet.
  let calling = Promise.resolve();

  function onCall(text) {
    calling = calling.then(() => runCall(text));
  }

  new QWebChannel(qt.webChannelTransport, (channel) => {
    bridge = channel.objects.rocklyBridge;
    bridge.toPage.connect(onCall);
    send({event: 'hello'});
  });
})();
