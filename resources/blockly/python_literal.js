/**
 * Python literals for whatever a user types: the generated Python must carry the exact
 * text as a string, never as code. Blockly's own quote_ turns a newline into a line
 * continuation (dropping it), so Rockly uses this for every string it generates.
 */
'use strict';

const RocklyPython = (() => {
  const hex = (value, width) => value.toString(16).padStart(width, '0');

  /** True for characters that must not appear raw inside a Python string literal. */
  function needsEscape(codePoint) {
    return codePoint < 0x20 || (codePoint >= 0x7f && codePoint < 0xa0) ||
        codePoint === 0x2028 || codePoint === 0x2029 || codePoint === 0xfeff ||
        (codePoint >= 0xd800 && codePoint <= 0xdfff);
  }

  /** A single-quoted Python str literal whose value is exactly `text`. */
  function string(text) {
    const named = {'\\': '\\\\', "'": "\\'", '\n': '\\n', '\r': '\\r', '\t': '\\t'};
    let out = "'";
    for (const character of String(text)) {
      const codePoint = character.codePointAt(0);
      if (named[character]) {
        out += named[character];
      } else if (needsEscape(codePoint)) {
        out += codePoint <= 0xff ? '\\x' + hex(codePoint, 2) : '\\u' + hex(codePoint, 4);
      } else {
        out += character;
      }
    }
    return out + "'";
  }

  /** A Python literal for a JSON-like value (string, number, boolean, null). */
  function literal(value) {
    if (value === null || value === undefined) return 'None';
    if (value === true) return 'True';
    if (value === false) return 'False';
    if (typeof value === 'number') {
      if (Number.isFinite(value)) return String(value);
      return "float('" + (Number.isNaN(value) ? 'nan' : value > 0 ? 'inf' : '-inf') + "')";
    }
    return string(value);
  }

  return {string, literal};
})();
