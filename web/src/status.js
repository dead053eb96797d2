// The one-line message area: errors in red, notes in grey; the current model is never touched.
export class Status {
  constructor(el) {
    this.el = el;
  }
  error(message) {
    this.el.textContent = message;
    this.el.className = 'status error';
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
