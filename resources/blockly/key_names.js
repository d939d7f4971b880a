/**
 * The modifier keys in Blockly's shortcut labels (a menu item's "Control + Z", a hint's "Control + V"), in
 * the page's language: Blockly takes those names from its messages once, when it loads, before any
 * language's messages are there, so it always says "Control" and "Alt". Every label it adds to the page
 * is put in the words of Blockly.Msg.CONTROL_KEY and ALT_KEY as it appears.
 */
'use strict';

const RocklyKeyNames = (() => {
  const LABELS = '.blocklyShortcut, .blocklyToast';

  function translate(element) {
    const names = {Control: Blockly.Msg.CONTROL_KEY, Alt: Blockly.Msg.ALT_KEY};
    const walker = document.createTreeWalker(element, NodeFilter.SHOW_TEXT);
    for (let node = walker.nextNode(); node; node = walker.nextNode()) {
      const said = node.data.replace(/\b(Control|Alt)\b(?= \+ )/g, (word) => names[word] || word);
      if (said !== node.data) node.data = said;
    }
  }

  function onAdded(records) {
    for (const record of records) {
      for (const added of record.addedNodes) {
        if (added.nodeType !== Node.ELEMENT_NODE) continue;
        if (added.matches(LABELS)) translate(added);
        for (const label of added.querySelectorAll(LABELS)) translate(label);
      }
    }
  }

  /** Translate every shortcut label Blockly adds to the page from now on. */
  let observer = null;
  function watch() {
    if (observer) return;
    observer = new MutationObserver(onAdded);
    observer.observe(document.body, {childList: true, subtree: true});
  }

  return {watch};
})();
