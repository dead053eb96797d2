// Share links: the model in the URL fragment (#m=2.…; m=1.… still opens), never sent to a server.
export function linkFromLocation() {
  return linkFromHash(window.location.hash);
}

/** The fragment without '#' when it holds a model (an `m=` parameter), else null. Pure (tests). */
export function linkFromHash(hash) {
  const fragment = hash.replace(/^#/, '');
  return /(^|&)m=/.test(fragment) ? fragment : null;
}

/**
 * The resolution a link's model was made at (`r=22` beside `m=…`, which the page adds: the model's
 * own data has no resolution), or 0. Pure (tests).
 */
export function resolutionFromLink(link) {
  const m = /(?:^|[#&])r=(\d{1,3})(?:&|$)/.exec(String(link));
  return m ? Number(m[1]) : 0;
}

/** The fragment `m=…` with the model's resolution beside it (none when unknown). */
export function fragmentWithResolution(fragment, resolution) {
  return resolution > 0 ? `${fragment}&r=${resolution}` : fragment;
}

export function pageUrlWith(fragment) {
  return urlWithFragment(window.location.href, fragment);
}

/** `href` with its fragment replaced (query kept). Pure (tests). */
export function urlWithFragment(href, fragment) {
  const url = new URL(href);
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
