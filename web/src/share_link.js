// Share links: the model in the URL fragment (#m=1.…), never sent to a server.
export function linkFromLocation() {
  const hash = window.location.hash.replace(/^#/, '');
  return /(^|&)m=/.test(hash) ? hash : null;
}

export function pageUrlWith(fragment) {
  const url = new URL(window.location.href);
  url.hash = fragment;
  return url.href;
}

/** Copies text to the clipboard; falls back to a prompt-free selection of a hidden field. */
export async function copyText(text) {
  try {
    await navigator.clipboard.writeText(text);
    return true;
  } catch {
    const area = document.createElement('textarea');
    area.value = text;
    document.body.append(area);
    area.select();
    const ok = document.execCommand('copy');
    area.remove();
    return ok;
  }
}
