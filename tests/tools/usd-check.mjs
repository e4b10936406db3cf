// usd-check: reads a .usda crowd with tinyusdz and reports what it finds (see usd-check).
//
// tinyusdz parses the file, composes its variants, references and inherits, and converts
// the composed stage into its render scene (meshes, materials, evaluated transforms).
// This script reads only what tinyusdz hands back: the render scene's nodes, and the
// composed layer as tinyusdz writes it out again (its own parsed values, printed).
import { spawnSync } from 'node:child_process';
import fs from 'node:fs';
import os from 'node:os';
import path from 'node:path';
import { pathToFileURL } from 'node:url';

const VERSION = process.env.TINYUSDZ_VERSION || '0.9.0-rc10';
const usage = 'usage: usd-check [--json-out FILE] [--expect-agents N] FILE.usda';

function die(code, message) {
  console.error(`usd-check: ${message}`);
  console.log(JSON.stringify({ ok: false, error: message }));
  process.exit(code);
}

const args = process.argv.slice(2);
let jsonOut = null, expectAgents = null, file = null;
for (let i = 0; i < args.length; ++i) {
  if (args[i] === '--json-out') jsonOut = args[++i];
  else if (args[i] === '--expect-agents') expectAgents = Number(args[++i]);
  else if (args[i] === '--help' || args[i] === '-h') { console.log(usage); process.exit(0); }
  else if (args[i].startsWith('--')) die(2, `unknown option ${args[i]}\n${usage}`);
  else file = args[i];
}
if (!file) die(2, usage);
if (!fs.existsSync(file)) die(2, `no such file: ${file}`);

// tinyusdz, installed once.
const cacheRoot = process.env.THRONG_TOOLS_CACHE ||
  path.join(process.env.XDG_CACHE_HOME || path.join(os.homedir(), '.cache'), 'throng-tools');
const dir = path.join(cacheRoot, `tinyusdz-${VERSION}`);
const moduleDir = path.join(dir, 'node_modules', 'tinyusdz');
if (!fs.existsSync(path.join(moduleDir, 'tinyusdz.wasm'))) {
  console.error(`usd-check: npm install tinyusdz@${VERSION} -> ${dir} (one-time) ...`);
  const tmp = `${dir}.tmp-${process.pid}`;
  fs.mkdirSync(tmp, { recursive: true });
  const r = spawnSync('npm', ['install', '--prefix', tmp, '--no-audit', '--no-fund', '--no-save',
    '--omit=peer', `tinyusdz@${VERSION}`], { stdio: ['ignore', 'inherit', 'inherit'] });
  if (r.status !== 0) { fs.rmSync(tmp, { recursive: true, force: true }); die(2, 'npm install failed'); }
  fs.rmSync(dir, { recursive: true, force: true });
  fs.renameSync(tmp, dir);
}

// The WebAssembly build is made for browsers: let it believe it is in one, and hand it
// its binary instead of a fetch.
process.type = 'renderer';
globalThis.window = globalThis;
const { default: initTinyUSDZ } = await import(pathToFileURL(path.join(moduleDir, 'tinyusdz.js')).href);
const native = await initTinyUSDZ({ wasmBinary: fs.readFileSync(path.join(moduleDir, 'tinyusdz.wasm')) });

const layer = new native.TinyUSDZLoaderNative();
if (!layer.loadAsLayerFromBinary(new Uint8Array(fs.readFileSync(file)), path.basename(file)))
  die(1, `tinyusdz cannot parse ${file}: ${layer.error()}`);
for (let pass = 0; pass < 3; ++pass)
  for (const arc of ['Variants', 'References', 'Inherits'])
    if (!layer[`compose${arc}`]()) die(1, `tinyusdz cannot compose the ${arc.toLowerCase()}: ${layer.error()}`);
const composed = layer.layerToString();
if (!layer.layerToRenderScene()) die(1, `tinyusdz cannot convert the stage to a render scene: ${layer.error()}`);

// The stage's metadata, as tinyusdz wrote it.
const header = composed.slice(0, composed.indexOf('\n)'));
const meta = {};
for (const key of ['metersPerUnit', 'upAxis', 'startTimeCode', 'endTimeCode', 'timeCodesPerSecond',
  'framesPerSecond', 'defaultPrim']) {
  const m = header.match(new RegExp(`\\b${key} = "?([^"\\n]*)"?`));
  meta[key] = m ? (isNaN(Number(m[1])) ? m[1] : Number(m[1])) : null;
}

// The render scene: every agent's node, its evaluated place, its meshes and their materials.
const problems = [];
const nodes = new Map();
(function walk(n) { nodes.set(n.absPath, n); for (const c of n.children || []) walk(c); })(layer.getDefaultRootNode());
const agentsNode = nodes.get('/Crowd/Agents');
if (!agentsNode) die(1, 'no /Crowd/Agents in the render scene');
const meshes = [];
for (let i = 0; i < layer.numMeshes(); ++i) meshes.push(layer.getMesh(i));

// The lines of `attribute`'s time samples in a prim's text, as tinyusdz writes them: one
// "time: value," a line, closed by a line holding only "}".
function sampleLines(text, attribute) {
  const at = text.indexOf(`${attribute}.timeSamples = {`);
  if (at < 0) return null;
  const lines = [];
  for (const line of text.slice(text.indexOf('\n', at) + 1).split('\n')) {
    if (/^\s*}\s*$/.test(line)) break;
    lines.push(line);
  }
  return lines;
}
// [[time, numbers or token], …].
function samples(text, attribute) {
  const lines = sampleLines(text, attribute);
  if (!lines) return null;
  const out = [];
  for (const line of lines) {
    const m = line.match(/^\s*([-\d.e+]+):\s*(.*?),?\s*$/);
    if (!m) continue;
    out.push([Number(m[1]), m[2].startsWith('"') ? m[2].replace(/"/g, '') : (m[2].match(/[-\d.e+]+/g) || []).map(Number)]);
  }
  return out;
}
// Array samples: [[time, how many tuples], …].
function arraySamples(text, attribute) {
  const lines = sampleLines(text, attribute);
  if (!lines) return null;
  const out = [];
  for (const line of lines) {
    const m = line.match(/^\s*([-\d.e+]+):\s*\[(.*)\]/);
    if (m) out.push([Number(m[1]), (m[2].match(/\(([^)]*)\)/g) || []).length]);
  }
  return out;
}
function tokens(text, attribute) {
  const m = text.match(new RegExp(`${attribute.replace(/[[\]]/g, '\\$&')} = \\[([^\\]]*)\\]`));
  return m ? (m[1].match(/"[^"]*"/g) || []).length : null;
}

// Value clips: each clip layer read once with tinyusdz, its SkelAnimations by path.
const clipLayers = new Map();
function clipLayer(asset) {
  if (clipLayers.has(asset)) return clipLayers.get(asset);
  const where = path.resolve(path.dirname(file), asset);
  let prims = null;
  if (fs.existsSync(where)) {
    const clips = new native.TinyUSDZLoaderNative();
    if (!clips.loadAsLayerFromBinary(new Uint8Array(fs.readFileSync(where)), path.basename(where)))
      die(1, `tinyusdz cannot parse the clips layer ${where}: ${clips.error()}`);
    const text = clips.layerToString();
    prims = new Map();
    for (const m of text.matchAll(/def SkelAnimation "([^"]+)"/g)) {
      const start = m.index;
      const lineStart = text.lastIndexOf('\n', start) + 1;
      const close = text.indexOf(`\n${text.slice(lineStart, start)}}`, start);
      const body = text.slice(start, close < 0 ? text.length : close);
      const rotations = arraySamples(body, 'quatf[] rotations') || [];
      prims.set(`/Clips/${m[1]}`, {
        joints: tokens(body, 'uniform token[] joints'),
        samples: rotations.length,
        lengths: [...new Set(rotations.concat(arraySamples(body, 'float3[] translations') || []).map((r) => r[1]))],
      });
    }
  }
  clipLayers.set(asset, prims);
  return prims;
}

const agents = [];
for (const node of agentsNode.children || []) {
  const name = node.primName;
  const start = composed.indexOf(`def SkelRoot "${name}"`);
  if (start < 0) { problems.push(`${name}: not a SkelRoot`); continue; }
  // The prim's text: up to the "}" at its own indentation.
  const lineStart = composed.lastIndexOf('\n', start) + 1;
  const close = composed.indexOf(`\n${composed.slice(lineStart, start)}}`, start);
  const text = composed.slice(start, close < 0 ? composed.length : close);
  const anim = text.slice(text.indexOf('def SkelAnimation'));
  const skel = text.slice(text.indexOf('def Skeleton'));
  const animJoints = tokens(anim, 'uniform token[] joints');
  const skelJoints = text.indexOf('def Skeleton') >= 0 ? tokens(skel, 'uniform token[] joints') : null;
  const rotations = arraySamples(anim, 'quatf[] rotations') || [];
  const translations = arraySamples(anim, 'float3[] translations') || [];
  // A value clip in place of its own samples (compact): the layer, the prim, the times.
  let clip = null;
  const clipsAt = anim.indexOf('clips = {');
  if (clipsAt >= 0) {
    const asset = (anim.slice(clipsAt).match(/assetPaths = \[@([^@]*)@\]/) || [])[1];
    const primPath = (anim.slice(clipsAt).match(/primPath = "([^"]*)"/) || [])[1];
    const timesText = (anim.slice(clipsAt).match(/double2\[\] times = \[([^\]]*)\]/) || [])[1] || '';
    const times = [...timesText.matchAll(/\(([-\d.e+]+),\s*([-\d.e+]+)\)/g)].map((m) => [Number(m[1]), Number(m[2])]);
    const layerPrims = asset ? clipLayer(asset) : null;
    const target = layerPrims && layerPrims.get(primPath);
    clip = { asset, primPath, times, samples: target ? target.samples : 0, joints: target ? target.joints : null };
    if (!layerPrims) problems.push(`${name}: clips layer ${asset} missing`);
    else if (!target) problems.push(`${name}: no ${primPath} in ${asset}`);
    else {
      if (target.joints !== skelJoints) problems.push(`${name}: ${primPath} animates ${target.joints} joints, the skeleton has ${skelJoints}`);
      if (target.lengths.some((n) => n !== target.joints)) problems.push(`${primPath}: a sample's length is not its joint count`);
      for (let k = 0; k < times.length; ++k) {
        if (times[k][1] < 0 || times[k][1] > target.samples - 1) { problems.push(`${name}: clip time ${times[k][1]} outside ${primPath}`); break; }
        if (k > 0 && !(times[k][0] > times[k - 1][0])) { problems.push(`${name}: clip stage times not increasing`); break; }
      }
    }
  }
  const scaleMatch = text.match(/xformOp:scale = \(([-\d.e+]+)/);
  const agentMeshes = meshes.filter((m) => m.absPath.startsWith(`${node.absPath}/`));
  const g = node.globalMatrix;
  const agent = {
    name,
    first: [g[12], g[13], g[14]],
    translate: samples(text, 'xformOp:translate') || [],
    orient: samples(text, 'xformOp:orient') || [],
    visibility: samples(text, 'token visibility') || [],
    animJoints, skelJoints,
    rotationSamples: rotations.length,
    clip,
    scale: scaleMatch ? Number(scaleMatch[1]) : 1,
    meshes: agentMeshes.length,
    unboundMeshes: agentMeshes.filter((m) => m.materialId < 0).length,
  };
  if (!text.includes(`rel skel:animationSource = <${node.absPath}/Anim>`)) problems.push(`${name}: no animation source`);
  if (animJoints === null || skelJoints === null) problems.push(`${name}: no skeleton or no animation`);
  else if (animJoints !== skelJoints) problems.push(`${name}: ${animJoints} animated joints, ${skelJoints} in the skeleton`);
  if (!clip && rotations.length === 0 && !/quatf\[\] rotations = \[/.test(anim))
    problems.push(`${name}: its animation has no rotations`);
  for (const [t, n] of rotations.concat(translations))
    if (n !== animJoints) { problems.push(`${name}: ${n} values at time ${t} for ${animJoints} joints`); break; }
  if (agent.translate.length === 0) problems.push(`${name}: no root motion`);
  if (agentMeshes.length === 0) problems.push(`${name}: no mesh`);
  agents.push(agent);
}
if (expectAgents !== null && agents.length !== expectAgents)
  problems.push(`${agents.length} agents, expected ${expectAgents}`);

const crowd = nodes.get('/Crowd').globalMatrix;
const summary = {
  ok: problems.length === 0,
  file,
  ...meta,
  origin: [crowd[12], crowd[13], crowd[14]],
  agents: agents.length,
  meshes: meshes.length,
  agentMeshes: agents.reduce((s, a) => s + a.meshes, 0),
  clippedAgents: agents.filter((a) => a.clip).length,
  unboundAgentMeshes: agents.reduce((s, a) => s + a.unboundMeshes, 0),
  setMeshes: meshes.filter((m) => m.absPath.startsWith('/Crowd/Set/')).length,
  lamps: [...nodes.keys()].filter((p) => /^\/Crowd\/Set\/lamp_/.test(p)).length,
  problems: problems.slice(0, 20),
};
if (jsonOut) fs.writeFileSync(jsonOut, JSON.stringify({ ...summary, agentList: agents }));
for (const p of problems.slice(0, 20)) console.error(`usd-check: ${p}`);
console.log(`usd-check: ${agents.length} agents, ${meshes.length} meshes, time codes ${meta.startTimeCode}..${meta.endTimeCode} at ${meta.timeCodesPerSecond}/s`);
console.log(JSON.stringify(summary));
process.exit(problems.length === 0 ? 0 : 1);
