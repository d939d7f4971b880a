/**
 * Number fields read and show numbers the page's language's way: in German "2,5" is 2.5 and shows as
 * 2,5; in English "2,5" is refused (Blockly's own field dropped the comma and read 25) and "1,000" is
 * 1000 only as groups of three. The field's value, the Python and the saved file keep 2.5. The same
 * grammar as core/numbers.py's `read_number`, which reads numbers on the Qt side.
 */
'use strict';

const RocklyNumbers = (() => {
  const ENGLISH = {point: '.', group: ','};
  const MARKS = {de: {point: ',', group: '.'}};
  let marks = ENGLISH;
  let refusedText = '';

  const escape = (mark) => mark.replace(/[.*+?^${}()|[\]\\]/g, '\\$&');

  function pattern({point, group}) {
    const p = escape(point);
    const g = escape(group);
    return new RegExp(`^[+-]?(?=${p}?\\d)(?:\\d{1,3}(?:${g}\\d{3})+|\\d+)?(?:${p}\\d+)?(?:e[+-]?\\d+)?$`, 'i');
  }

  /** Read and show numbers in `language` from now on; `refused` says a typed text is no number. */
  function setLanguage(language, refused) {
    marks = MARKS[String(language).split(/[_-]/)[0]] || ENGLISH;
    refusedText = refused || '';
  }

  /** The number typed as `text`, NaN for a text that is no number (or could be read two ways). */
  function read(text) {
    const typed = String(text).trim().replace(/\u2212/g, '-').replace(/[ \u202f]/g, '');
    if (!pattern(marks).test(typed)) return NaN;
    return Number(typed.split(marks.group).join('').replace(marks.point, '.'));
  }

  /** `value` written with the language's decimal mark, never grouped: read back as the same number. */
  function text(value) {
    return String(value).replace('.', marks.point);
  }

  /** The refusal shown under a number field's editor while its text is no number. */
  function showRefusal(field) {
    const div = Blockly.WidgetDiv.getDiv();
    let note = div && div.querySelector('.rocklyNumberRefused');
    const typed = field.htmlInput_ ? field.htmlInput_.value : '';
    const refused = Boolean(div) && Boolean(typed.trim()) && Number.isNaN(read(typed));
    if (!refused) {
      if (note) note.remove();
      return;
    }
    if (!note) {
      note = document.createElement('div');
      note.className = 'rocklyNumberRefused';
      note.setAttribute('role', 'alert');
      div.appendChild(note);
    }
    note.textContent = refusedText;
  }

  const number = Blockly.FieldNumber.prototype;
  number.getText_ = function() {
    if (this.isBeingEdited_ && this.htmlInput_) return this.htmlInput_.value;
    return text(this.getValue());
  };
  number.getEditorText_ = (value) => text(value);
  // NaN is refused by FieldNumber's own check: the editor shows the text as wrong, and keeps the old value.
  number.getValueFromEditorText_ = (typed) => read(typed);
  const onInput = number.onHtmlInputChange;
  number.onHtmlInputChange = function(event) {
    onInput.call(this, event);
    showRefusal(this);
  };
  const dispose = number.widgetDispose_;
  number.widgetDispose_ = function() {
    const div = Blockly.WidgetDiv.getDiv();
    const note = div && div.querySelector('.rocklyNumberRefused');
    if (note) note.remove();
    dispose.call(this);
  };

  return {setLanguage, read, text};
})();
