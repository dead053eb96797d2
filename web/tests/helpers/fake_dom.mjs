// Just enough of the DOM for the page's modules to run in Node (no jsdom dependency): elements
// with value/textContent/children/listeners, a root whose querySelector('#id') finds them, and a
// document with createElement and a body. Values are stored as strings, as real inputs do.
export class FakeElement {
  constructor(tag = 'div', id = '') {
    Object.assign(this, { tagName: tag.toUpperCase(), id, className: '', hidden: false,
      disabled: false, children: [], parent: null, dataset: {}, style: {}, listeners: {} });
    this._text = '';
    this.classes = new Set();
    this.classList = {
      add: (c) => this.classes.add(c),
      remove: (c) => this.classes.delete(c),
      contains: (c) => this.classes.has(c),
      toggle: (c, on) => (on ? this.classes.add(c) : this.classes.delete(c)),
    };
    this._value = '';
  }
  get textContent() { return this._text; }
  set textContent(t) { // as in the DOM: the text replaces the children
    this._text = t;
    this.children = [];
  }
  get value() { return this._value; }
  set value(v) { this._value = String(v); }
  addEventListener(type, fn) { (this.listeners[type] ??= []).push(fn); }
  dispatch(type, event = {}) { for (const fn of this.listeners[type] || []) fn(event); }
  append(...nodes) { for (const n of nodes) this.adopt(n, this.children.length); }
  prepend(...nodes) { nodes.reverse().forEach((n) => this.adopt(n, 0)); }
  adopt(node, at) {
    if (typeof node !== 'object') node = Object.assign(new FakeElement('#text'), { textContent: String(node) });
    node.parent = this;
    this.children.splice(at, 0, node);
  }
  replaceChildren(...nodes) { this.children = []; this.append(...nodes); }
  add(node) { this.append(node); } // <select>.add(option)
  remove() {
    if (this.parent) this.parent.children = this.parent.children.filter((c) => c !== this);
    this.parent = null;
  }
  select() {}
  /** The visible text of this element and its children, as the page shows it. */
  get text() { return this.textContent + this.children.map((c) => c.text).join(''); }
}

/** A root whose querySelector('#id') returns one element per id (made on first use). */
export function fakeRoot(initialValues = {}) {
  const elements = new Map();
  const root = {
    elements,
    querySelector(selector) {
      const id = selector.replace(/^#/, '');
      if (!elements.has(id)) elements.set(id, new FakeElement('div', id));
      return elements.get(id);
    },
  };
  for (const [id, v] of Object.entries(initialValues)) root.querySelector('#' + id).value = v;
  return root;
}

/** A document: createElement, body, execCommand (copy result settable). */
export function fakeDocument({ copyResult = true } = {}) {
  const doc = {
    body: new FakeElement('body'),
    baseURI: 'http://127.0.0.1:8080/app/',
    commands: [],
    createElement: (tag) => new FakeElement(tag),
    execCommand(command) {
      doc.commands.push({ command, bodyChildren: doc.body.children.map((c) => c.value) });
      return copyResult;
    },
  };
  return doc;
}

/** Sets a global (navigator, document, fetch …) for one test; returns a function restoring it. */
export function setGlobal(name, value) {
  const before = Object.getOwnPropertyDescriptor(globalThis, name);
  Object.defineProperty(globalThis, name, { value, configurable: true, writable: true });
  return () => {
    if (before) Object.defineProperty(globalThis, name, before);
    else delete globalThis[name];
  };
}
