// The page around the viewer: reads the address, chooses the threaded build when the page may use threads,
// keeps the viewer's stores in the browser's storage (IndexedDB), and carries files between the user's disk
// and the viewer's file system. The viewer calls nomePage.* back (web/src/web_main.cpp).
'use strict';

const params = new URLSearchParams(location.search);
const logElement = document.getElementById('log');
const message = document.getElementById('message');
const loadStart = performance.now();
const home = '/home/web_user';

function logLine(text) {
  logElement.textContent += text + '\n';
  console.log(text);
}

// Bundled scenes are named as in the examples list ("funnel_cube.nome", "jipcad/..."); anything else is
// fetched from the page's server (a path beside the page, or an address that allows it).
async function sceneArgument(name) {
  if (bundledScenes.includes(name)) return '/scenes/' + name;
  if (bundledScenes.includes(name + '.nome')) return '/scenes/' + name + '.nome';
  const response = await fetch(name);
  if (!response.ok) throw new Error(name + ': ' + response.status + ' ' + response.statusText);
  const file = home + '/' + decodeURIComponent(name.split('/').pop().split('?')[0]);
  const modified = Date.parse(response.headers.get('Last-Modified'));
  pendingFiles.push([file, new Uint8Array(await response.arrayBuffer()), isNaN(modified) ? undefined : modified]);
  return file;
}

let bundledScenes = [];
// [path, bytes, modified (ms since 1970) where the origin tells]
const pendingFiles = [];

// A file the viewer opens keeps its origin's date, not the moment this visit wrote it: the viewer offers
// the recovery of unsaved changes only when the recovery file is newer than the document.
function writeFile(path, data, modified) {
  FS.writeFile(path, data);
  if (modified !== undefined) FS.utime(path, modified, modified);
}

window.nomePage = {
  pickFile() { document.getElementById('file').click(); },
  download(path) {
    const data = FS.readFile(path);
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([data]));
    link.download = path.split('/').pop();
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10000);
  },
  modelShown() {
    const ms = Math.round(performance.now() - loadStart);
    document.title = 'Nome';
    logLine('page: first model frame ' + ms + ' ms after load');
    document.body.dataset.firstModelMs = ms;
  },
  scriptDone() {
    document.body.dataset.scriptsDone = Number(document.body.dataset.scriptsDone || 0) + 1;
  },
  // Writes the layout and the stores to the browser's storage; resolves once they are there.
  keepState() {
    Module.ccall('nome_keep_layout', null, [], []);
    return new Promise((resolve) => FS.syncfs(false, (error) => resolve(!error)));
  },
  finished(status) {
    logLine('page: the viewer quit with status ' + status);
    document.body.dataset.exitStatus = status;
  },
  failed(text) { message.textContent = text; message.style.display = ''; },
};

function openUserFile(file) {
  const reader = new FileReader();
  reader.onload = () => {
    FS.mkdirTree(home + '/uploads');
    const path = home + '/uploads/' + file.name.replace(/\//g, '_');
    writeFile(path, new Uint8Array(reader.result), file.lastModified);
    Module.ccall('nome_open', null, ['string'], [path]);
  };
  reader.readAsArrayBuffer(file);
}

document.addEventListener('visibilitychange', () => {
  if (document.visibilityState === 'hidden' && window.FS) nomePage.keepState();
});
document.getElementById('open').onclick = () => nomePage.pickFile();
document.getElementById('file').onchange = (event) => {
  for (const file of event.target.files) openUserFile(file);
  event.target.value = '';
};
document.getElementById('examples').onchange = (event) => {
  if (!event.target.value) return;
  const address = new URL(location.href);
  address.searchParams.set('scene', event.target.value);
  location.href = address.toString();
};

// Runs script commands in the open viewer, one a line (the desktop's `nome --script` commands).
window.nomeScript = (text) => Module.ccall('nome_script', 'number', ['string'], [text]) === 1;

async function start() {
  bundledScenes = await (await fetch('scenes.json')).json();
  const examples = document.getElementById('examples');
  for (const name of bundledScenes) examples.add(new Option(name, name));

  const args = [];
  try {
    if (params.has('source')) {
      pendingFiles.push([home + '/scene.nome', new TextEncoder().encode(params.get('source'))]);
      args.push(home + '/scene.nome');
    } else {
      args.push(await sceneArgument(params.get('scene') || 'funnel_cube.nome'));
    }
  } catch (error) {
    message.textContent = 'Could not load the scene: ' + error.message;
    return;
  }
  if (params.has('script')) {
    pendingFiles.push(['/tmp/page_script.txt', new TextEncoder().encode(params.get('script').replace(/;/g, '\n'))]);
    args.push('--script', '/tmp/page_script.txt');
  }

  const threads = params.get('threads') !== '0' && window.crossOriginIsolated === true;
  document.getElementById('threads').textContent =
    threads ? navigator.hardwareConcurrency + ' threads' : 'one thread';
  logLine(threads ? 'page: threads build, ' + navigator.hardwareConcurrency + ' threads' : 'page: one-thread build');
  window.Module = {
    arguments: args,
    canvas: document.getElementById('canvas'),
    print: logLine,
    printErr: logLine,
    preRun: [() => {
      ENV.HOME = home;
      ENV.XDG_CONFIG_HOME = '/persist/config';
      ENV.XDG_STATE_HOME = '/persist/state';
      FS.mkdirTree(home);
      for (const [path, data, modified] of pendingFiles) writeFile(path, data, modified);
      // The layout, recent files and crash recovery live in IndexedDB across visits. A browser that keeps
      // no storage (private windows, some headless runs) answers late or never: the viewer then starts
      // without it after a second.
      FS.mkdir('/persist');
      FS.mount(IDBFS, {}, '/persist');
      addRunDependency('persist');
      let isRead = false;
      const startViewer = () => {
        if (isRead) return;
        isRead = true;
        removeRunDependency('persist');
      };
      FS.syncfs(true, (error) => {
        if (error) logLine('page: the browser storage could not be read: ' + error);
        startViewer();
      });
      setTimeout(startViewer, 1000);
      let isSaving = false;
      setInterval(() => {
        if (isSaving) return;
        isSaving = true;
        FS.syncfs(false, () => { isSaving = false; });
      }, 2000);
    }],
    onRuntimeInitialized() {
      message.style.display = 'none';
      // The bundled scenes are unpacked anew on each visit and never change: one date for all visits.
      for (const name of bundledScenes) FS.utime('/scenes/' + name, 0, 0);
    },
  };
  const script = document.createElement('script');
  script.src = threads ? 'nome-threads.js' : 'nome.js';
  script.onerror = () => nomePage.failed('Could not load ' + script.src);
  document.body.appendChild(script);
}

start();
