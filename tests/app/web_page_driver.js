// Drives the web page in headless Chromium (SwiftShader's WebGL2) through the DevTools protocol, with node's
// own WebSocket (node --experimental-websocket): opens the address, waits until the viewer has drawn its model
// and run the address's script, picks FILE in the page's Open dialog when given (as a user choosing a file on
// their disk), runs SCRIPT through the page's nomeScript() when given, then prints the page's log and writes a
// picture of the page. Downloads the page offers land in DOWNLOADS when given.
//   node --experimental-websocket web_page_driver.js ADDRESS PICTURE.png [SCRIPT [FILE [DOWNLOADS]]]
'use strict';

const { spawn } = require('child_process');
const fs = require('fs');
const os = require('os');
const path = require('path');

const [address, picture, script, upload, downloads] = process.argv.slice(2);
const patienceMs = Number(process.env.NOME_PAGE_PATIENCE_MS || 90000);
// NOME_PAGE_PROFILE keeps the browser's profile (its storage) for a later run; otherwise it is a fresh one.
const keptProfile = process.env.NOME_PAGE_PROFILE;
const profile = keptProfile || fs.mkdtempSync(path.join(os.tmpdir(), 'nome-page-'));
const browser = spawn('chromium', [
  '--headless=new', '--no-sandbox', '--use-angle=swiftshader', '--enable-unsafe-swiftshader',
  '--hide-scrollbars', '--window-size=1280,800', '--remote-debugging-port=0', '--user-data-dir=' + profile,
  'about:blank',
], { stdio: ['ignore', 'ignore', 'pipe'] });

// The profile goes once Chromium has exited; its helper processes may still write there a moment longer.
function finish(status, message) {
  if (message) console.error(message);
  const leave = () => setTimeout(() => {
    if (keptProfile) process.exit(status);
    try {
      fs.rmSync(profile, { recursive: true, force: true, maxRetries: 5 });
    } catch (error) {
      console.error('left ' + profile + ': ' + error.message);
    }
    process.exit(status);
  }, 200);
  if (browser.exitCode !== null || browser.signalCode !== null) return leave();
  browser.once('exit', leave);
  browser.kill('SIGKILL');
}
// The page's log so far, once the page answers: what a page that never finishes printed says why.
let pageLog = async () => '';
setTimeout(async () => {
  const log = await Promise.race([pageLog().catch(() => ''), new Promise((r) => setTimeout(() => r(''), 2000))]);
  finish(1, log + 'the page did not finish within ' + patienceMs / 1000 + ' s');
}, patienceMs);

// Chromium prints its DevTools address on stderr once it listens.
function devtoolsAddress() {
  return new Promise((resolve, reject) => {
    let text = '';
    browser.stderr.on('data', (chunk) => {
      text += chunk;
      const found = text.match(/DevTools listening on (ws:\/\/\S+)/);
      if (found) resolve(found[1]);
    });
    browser.on('exit', (code) => reject(new Error('chromium exited with ' + code + ':\n' + text)));
  });
}

async function pageSocket() {
  const browserAddress = new URL(await devtoolsAddress());
  const targets = await (await fetch('http://' + browserAddress.host + '/json/list')).json();
  const target = targets.find((t) => t.type === 'page');
  const socket = new WebSocket(target.webSocketDebuggerUrl);
  await new Promise((resolve, reject) => {
    socket.onopen = resolve;
    socket.onerror = reject;
  });
  let next = 0;
  const pending = new Map();
  socket.onmessage = (event) => {
    const message = JSON.parse(event.data);
    if (message.id === undefined || !pending.has(message.id)) return;
    const { resolve, reject } = pending.get(message.id);
    pending.delete(message.id);
    if (message.error) reject(new Error(JSON.stringify(message.error)));
    else resolve(message.result);
  };
  return (method, params = {}) => new Promise((resolve, reject) => {
    pending.set(++next, { resolve, reject });
    socket.send(JSON.stringify({ id: next, method, params }));
  });
}

async function main() {
  const send = await pageSocket();
  const evaluate = async (expression) =>
    (await send('Runtime.evaluate', { expression, awaitPromise: true, returnByValue: true })).result.value;
  const waitFor = async (expression) => {
    while (!(await evaluate(expression))) await new Promise((resolve) => setTimeout(resolve, 50));
  };
  const scriptsDone = () => evaluate('Number(document.body.dataset.scriptsDone || 0)');
  pageLog = () => evaluate('document.getElementById("log").textContent');

  await send('Page.enable');
  await send('Emulation.setDeviceMetricsOverride', { width: 1280, height: 800, deviceScaleFactor: 1, mobile: false });
  await send('Page.navigate', { url: address });
  await waitFor('document.body && document.body.dataset.firstModelMs !== undefined');
  if (new URL(address).searchParams.has('script')) await waitFor('document.body.dataset.scriptsDone');
  if (downloads) await send('Page.setDownloadBehavior', { behavior: 'allow', downloadPath: downloads });
  if (upload) {
    const root = await send('DOM.getDocument');
    const input = await send('DOM.querySelector', { nodeId: root.root.nodeId, selector: '#file' });
    await send('DOM.setFileInputFiles', { nodeId: input.nodeId, files: [path.resolve(upload)] });
    // The window's title names the open file.
    await waitFor('document.title.includes(' + JSON.stringify(path.basename(upload)) + ')');
  }
  if (script) {
    const before = await scriptsDone();
    if (!(await evaluate('nomeScript(' + JSON.stringify(script) + ')'))) finish(1, 'nomeScript refused the script');
    while ((await scriptsDone()) <= before) await new Promise((resolve) => setTimeout(resolve, 50));
  }
  // The page keeps its layout and stores as when it is hidden.
  await evaluate('nomePage.keepState()');
  // Two more frames: the last command's result is on the canvas.
  await evaluate('new Promise((r) => requestAnimationFrame(() => requestAnimationFrame(r)))');
  const shot = await send('Page.captureScreenshot', { format: 'png' });
  fs.writeFileSync(picture, Buffer.from(shot.data, 'base64'));
  process.stdout.write(await pageLog());
  // A download is written after its click: wait until no partial file is left.
  if (downloads) {
    const isWritten = () => fs.readdirSync(downloads).length > 0 &&
                            !fs.readdirSync(downloads).some((name) => name.endsWith('.crdownload'));
    for (let i = 0; i < 100 && !isWritten(); ++i) await new Promise((resolve) => setTimeout(resolve, 50));
  }
  finish(0);
}

main().catch((error) => finish(1, error.stack || String(error)));
