// The one-line message area: errors in red, notes in grey; the current model is never touched.
export class Status {
  constructor(el) {
    this.el = el;
  }
  /** `action` ({label, run}): a button after the message (an open sheet's "Give it a thickness"). */
  error(message, action = null) {
    this.el.textContent = message;
    this.el.className = 'status error';
    if (action) {
      const button = (this.el.ownerDocument || globalThis.document).createElement('button');
      button.className = 'status-action';
      button.textContent = action.label;
      button.addEventListener('click', () => {
        button.disabled = true;
        action.run();
      });
      this.el.append(' ', button);
    }
    console.warn('zomeify:', message);
  }
  note(message) {
    this.el.textContent = message;
    this.el.className = 'status note';
  }
  clear() {
    this.el.textContent = '';
    this.el.className = 'status';
  }
}
