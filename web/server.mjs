// Zero-dependency static server for the page (tests, `npm start`). Sends COOP/COEP so the page is
// cross-origin isolated and the threaded wasm build can use SharedArrayBuffer; COI=0 leaves them
// out (the page then falls back to the single-threaded build). Layout as vite's: /x is looked up
// in public/ then the web root; /node_modules/ maps to the project's node_modules (the page's
// importmap points there when it is served unbundled). ROOT=dist serves a `vite build` instead.
//   PORT=8080 node web/server.mjs        COI=0 PORT=8081 node web/server.mjs      ROOT=dist node web/server.mjs
import http from 'node:http';
import fs from 'node:fs/promises';
import path from 'node:path';
import { fileURLToPath } from 'node:url';

const here = path.dirname(fileURLToPath(import.meta.url));
const port = Number(process.env.PORT || 8080);
const host = process.env.HOST || '127.0.0.1';
const isolated = process.env.COI !== '0';
const roots = process.env.ROOT
  ? [path.resolve(here, process.env.ROOT)]
  : [path.join(here, 'public'), here];
const nodeModules = path.resolve(here, '..', 'node_modules');

const types = {
  '.html': 'text/html; charset=utf-8', '.js': 'text/javascript', '.mjs': 'text/javascript',
  '.css': 'text/css', '.json': 'application/json', '.wasm': 'application/wasm', '.svg': 'image/svg+xml',
  '.png': 'image/png', '.ico': 'image/x-icon', '.obj': 'text/plain', '.md': 'text/plain; charset=utf-8',
};

function candidates(urlPath) {
  if (urlPath.startsWith('/node_modules/')) return [path.join(nodeModules, urlPath.slice(14))];
  return roots.map((r) => path.join(r, urlPath));
}

async function findFile(urlPath) {
  for (const file of candidates(urlPath)) {
    const base = file.startsWith(nodeModules) ? nodeModules : roots.find((r) => file.startsWith(r));
    if (!base || !file.startsWith(base)) continue; // no escaping the served folders
    try {
      const stat = await fs.stat(file);
      if (stat.isDirectory()) {
        const index = path.join(file, 'index.html');
        await fs.access(index);
        return index;
      }
      return file;
    } catch { /* next candidate */ }
  }
  return null;
}

const server = http.createServer(async (req, res) => {
  const headers = { 'Cache-Control': 'no-cache' };
  if (isolated) {
    headers['Cross-Origin-Opener-Policy'] = 'same-origin';
    headers['Cross-Origin-Embedder-Policy'] = 'require-corp';
  }
  let urlPath;
  try {
    urlPath = decodeURIComponent(new URL(req.url, 'http://x').pathname);
  } catch {
    res.writeHead(400, headers).end('bad request');
    return;
  }
  const file = await findFile(path.posix.normalize(urlPath));
  if (!file) {
    res.writeHead(404, { ...headers, 'Content-Type': 'text/plain' }).end('not found');
    return;
  }
  const body = await fs.readFile(file);
  const type = types[path.extname(file).toLowerCase()] || 'application/octet-stream';
  res.writeHead(200, { ...headers, 'Content-Type': type, 'Content-Length': body.length });
  res.end(req.method === 'HEAD' ? undefined : body);
});

server.listen(port, host, () => {
  const note = isolated ? 'cross-origin isolated' : 'WITHOUT COOP/COEP: single-threaded fallback';
  console.log(`zomeify page: http://${host}:${port}/  (${note})`);
});
