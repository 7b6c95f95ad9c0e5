// The instructor station end to end, as an instructor uses it: a realtime federation
// (deploy/instructor-station.yaml: timing, I/O, flight, navigation, fedsim-ios) on its own DDS
// domain on 127.0.0.1, and the page in Debian's headless Chromium driven by playwright-core.
// It checks, each against a control that would show a false pass:
//   - the map shows the aircraft moving (its track grows; the symbol is drawn where it is),
//   - a plot receives data,
//   - a click on Freeze freezes the simulation (sim time and position stop; they moved before),
//     and the page shows the freeze confirmed by the federation,
//   - a reposition to an approach gate moves the aircraft there (confirmed),
//   - Run resumes it; a bad command is refused with the field named;
// and it takes the README's screenshot and prints the push rate and the page's frame rate.
//
//   node ios_browser_test.mjs --bin build/bin --source . --out DIR --domain N [--screenshot PNG]
import { chromium } from 'playwright-core';
import { spawn } from 'node:child_process';
import fs from 'node:fs';
import path from 'node:path';

const args = Object.fromEntries(process.argv.slice(2).reduce((pairs, a, i, all) => {
  if (a.startsWith('--')) pairs.push([a.slice(2), all[i + 1]]);
  return pairs;
}, []));
for (const required of ['bin', 'source', 'out', 'domain']) {
  if (!args[required]) { console.error(`ios_browser_test: --${required} is required`); process.exit(2); }
}
const chromiumPath = process.env.FEDSIM_CHROMIUM || '/usr/bin/chromium';
if (!fs.existsSync(chromiumPath)) {
  console.error(`ios_browser_test: no Chromium at ${chromiumPath} (deploy/install-deps.sh installs Debian's chromium)`);
  process.exit(1);
}

const sleep = (ms) => new Promise((r) => setTimeout(r, ms));
let failures = 0;
function check(ok, what, detail = '') {
  console.log(`${ok ? 'ok  ' : 'FAIL'} ${what}${detail ? ': ' + detail : ''}`);
  if (!ok) failures++;
}
async function waitFor(what, predicate, timeoutMs = 15000) {
  const until = Date.now() + timeoutMs;
  for (;;) {
    const value = await predicate();
    if (value) return value;
    if (Date.now() > until) throw new Error(`timed out waiting for ${what}`);
    await sleep(100);
  }
}

fs.rmSync(args.out, { recursive: true, force: true });
fs.mkdirSync(args.out, { recursive: true });
const portFile = path.join(args.out, 'ios.port');
const federation = spawn(path.join(args.bin, 'fedsim'),
  ['run', path.join(args.source, 'deploy/instructor-station.yaml'), '--duration', '150', '--domain', args.domain,
   '--out', args.out],
  { env: { ...process.env, FEDSIM_IOS_PORT: '0' }, stdio: ['ignore', 'pipe', 'pipe'] });
const federationLog = fs.createWriteStream(path.join(args.out, 'fedsim_run.log'));
federation.stdout.pipe(federationLog);
federation.stderr.pipe(federationLog);
const federationExit = new Promise((resolve) => federation.on('exit', (code, signal) => resolve({ code, signal })));

let browser;
try {
  const port = await waitFor('the station\'s port file', () =>
    fs.existsSync(portFile) && fs.readFileSync(portFile, 'utf8').trim(), 60000);
  const url = `http://127.0.0.1:${port}/`;
  console.log(`station at ${url}`);
  browser = await chromium.launch({
    executablePath: chromiumPath,
    args: ['--no-sandbox', '--disable-gpu', '--disable-quic', '--no-first-run', '--disable-background-networking',
           '--disable-component-update', '--disable-sync'],
  });
  const page = await browser.newPage({ viewport: { width: 1400, height: 1000 } });
  page.on('pageerror', (e) => { console.log('FAIL page error: ' + e.message); failures++; });
  await page.goto(url);
  const fedsim = (expression) => page.evaluate(expression);

  // Live data and the moving aircraft.
  await waitFor('pushes with the aircraft state', () =>
    fedsim(() => window.fedsim.track.length > 5 && window.fedsim.state.timing.run_state === 'run'), 60000);
  const now = () => fedsim(() => ({ p: window.fedsim.track.at(-1), t: window.fedsim.state.timing.sim_time_s,
                                    n: window.fedsim.track.length,
                                    plot: window.fedsim.plot.series[0].points.length }));
  const before = await now();
  // Two simulated seconds later (waited for, not slept: a loaded machine flies fewer frames).
  const after = await waitFor('two seconds of flight', async () => {
    const a = await now();
    return a.t >= before.t + 2 && a;
  });
  const movedM = Math.hypot((after.p.lat - before.p.lat) * 111320,
                            (after.p.lon - before.p.lon) * 111320 * Math.cos(after.p.lat * Math.PI / 180));
  check(movedM > 50 && after.n > before.n, 'the map shows the aircraft moving', `${movedM.toFixed(0)} m in ${(after.t - before.t).toFixed(1)} s, track ${before.n} -> ${after.n} points`);
  check(after.t > before.t, 'sim time runs before the freeze (control)', `${before.t.toFixed(2)} -> ${after.t.toFixed(2)} s`);
  check(after.plot > before.plot, 'a plot receives data', `${before.plot} -> ${after.plot} points`);
  // The symbol is drawn where the aircraft is: the map follows it, so it sits at the centre.
  const symbol = await fedsim(() => {
    const c = document.getElementById('map');
    const d = c.getContext('2d').getImageData(c.width / 2 - 4, c.height / 2 - 4, 9, 9).data;
    let yellow = 0;
    for (let i = 0; i < d.length; i += 4) yellow += d[i] > 200 && d[i + 1] > 160 && d[i + 2] < 120;
    return yellow;
  });
  check(symbol > 5, 'the aircraft symbol is drawn at the aircraft', `${symbol} symbol pixels at the centre`);
  const map = await fedsim(() => window.fedsim.map && { runways: window.fedsim.map.runways.length, ils: window.fedsim.map.ils.length });
  check(map && map.runways === 8 && map.ils === 2, 'the map has KSFO\'s runways and ILS feathers', JSON.stringify(map));

  // Freeze from the page.
  await page.click('#btn-freeze');
  await waitFor('the freeze confirmed', () => fedsim(() => window.fedsim.state.timing.run_state === 'freeze' &&
    window.fedsim.state.commands.some((c) => c.text === 'freeze' && c.status === 'confirmed')));
  // Frozen: frames go on ticking (a second of them, 50) while sim time and position stand still;
  // the first look a few frames after the confirmation, when no earlier state is on its way.
  const frozenNow = () => fedsim(() => ({ t: window.fedsim.state.timing.sim_time_s,
    lat: window.fedsim.state.topics['fedsim/aircraft_state'].f.latitude_rad, frame: window.fedsim.state.timing.frame }));
  const confirmed = await frozenNow();
  const frozen1 = await waitFor('frames after the freeze', async () => {
    const f = await frozenNow();
    return f.frame >= confirmed.frame + 10 && f;
  });
  const frozen2 = await waitFor('a second of frozen frames', async () => {
    const f = await frozenNow();
    return f.frame >= frozen1.frame + 50 && f;
  });
  check(frozen1.t === frozen2.t && frozen1.lat === frozen2.lat, 'Freeze freezes the simulation',
        `sim time ${frozen1.t} -> ${frozen2.t} s while frames tick (frame ${frozen1.frame} -> ${frozen2.frame})`);

  // Reposition to a 5 NM gate on KSFO 28R from the form.
  await page.fill('#form-runway input[name=gate_nm]', '5');
  await page.click('#form-runway button');
  const moved = await waitFor('the reposition confirmed', () => fedsim(() =>
    window.fedsim.state.commands.find((c) => c.text.startsWith('reposition to KSFO 28R gate 5.0') && c.status !== 'pending')));
  check(moved.status === 'confirmed', 'a reposition moves the aircraft to the gate', moved.evidence);

  // A bad command is refused with the field named, and nothing is sent.
  const refused = await fedsim(() => window.fedsim.sendCommand({ command: 'reposition', lat_deg: 95, lon_deg: 0, alt_ft: 0, heading_deg: 0 }));
  check(refused.error && refused.error.includes('lat_deg'), 'a bad command is refused by name', refused.error);

  // Run again.
  await page.click('#btn-run');
  await waitFor('running again', () => fedsim(() => window.fedsim.state.timing.run_state === 'run'));
  await page.selectOption('#plot-field', 'climb_rate_mps');
  await page.click('#plot-add');
  // The added climb rate plotted over five seconds (the README's screenshot shows it).
  await waitFor('five seconds of the climb rate plotted', () => fedsim(() => {
    const points = window.fedsim.plot.series.at(-1).points;
    return window.fedsim.plot.series.length > 1 && points.length > 1 && points.at(-1)[0] - points[0][0] >= 5;
  }));

  // Replay the last 30 s of the live ring through the flight federate, pause it, take control.
  const position = () => fedsim(() => {
    const f = window.fedsim.state.topics['fedsim/aircraft_state'].f;
    return { lat: f.latitude_rad * 180 / Math.PI, lon: f.longitude_rad * 180 / Math.PI, t: window.fedsim.state.wall_s,
             sim_t: window.fedsim.state.timing.sim_time_s };
  });
  /// The position once `what` holds of it (at most 15 s).
  const positionWhen = (what, predicate) => waitFor(what, async () => {
    const p = await position();
    return predicate(p) && p;
  });
  const metres = (a, b) => Math.hypot((a.lat - b.lat) * 111320, (a.lon - b.lon) * 111320 * Math.cos(a.lat * Math.PI / 180));
  const live = await position();
  await page.selectOption('#replay-last', '30');
  await page.click('#replay-ring');
  await waitFor('the replay running', () => fedsim(() => window.fedsim.state.replay.active && window.fedsim.state.replay.playing));
  const replayed = await positionWhen('the replayed position', (p) => metres(p, live) > 200);
  check(metres(replayed, live) > 200, 'the replay shows the aircraft where it was', `${metres(replayed, live).toFixed(0)} m from where it is live`);
  const replayedLater = await positionWhen('the replay moving on', (p) => metres(p, replayed) > 20);
  check(metres(replayedLater, replayed) > 20, 'the replay moves on (control)',
        `${metres(replayedLater, replayed).toFixed(0)} m in ${(replayedLater.t - replayed.t).toFixed(1)} s`);
  await page.click('#replay-pause');
  await waitFor('the replay paused', () => fedsim(() => !window.fedsim.state.replay.playing));
  // Paused, the federation runs on and the pushes (stamped with the station's wall clock) keep
  // coming: the first look at a push made after the pause, the second a second of pushes later.
  const pausedAt = await position();
  const paused1 = await positionWhen('a push after the pause', (p) => p.t >= pausedAt.t + 0.3);
  const paused2 = await positionWhen('a second of pushes while paused', (p) => p.t >= paused1.t + 1);
  check(metres(paused1, paused2) < 0.01, 'a paused replay holds the aircraft', `${metres(paused1, paused2).toFixed(3)} m in 1 s while the federation runs`);
  await page.click('#replay-take');
  await waitFor('control taken', () => fedsim(() => !window.fedsim.state.replay.active));
  // 1.5 simulated seconds after taking control (the aircraft flies at about 60 m/s).
  const taken = await position();
  const flown = await positionWhen('1.5 s flown after taking control', (p) => p.sim_t >= taken.sim_t + 1.5);
  const fromPause = metres(flown, paused2);
  check(fromPause > 20 && fromPause < 250, 'taking control flies on from the replayed state', `${fromPause.toFixed(0)} m from it 1.5 s later`);
  // The push and frame rates below are measured over wall time: two seconds of it, on purpose.
  await sleep(2000);
  const stats = await fedsim(() => ({ fps: window.fedsim.stats.fps, push: window.fedsim.state.server.push_hz_measured,
                                      pushes: window.fedsim.pushes, hz: window.fedsim.state.server.push_hz }));
  console.log(`page frame rate ${stats.fps} fps; pushes ${stats.push.toFixed(2)}/s measured by the server ` +
              `(configured ${stats.hz}/s), ${stats.pushes} received`);
  check(stats.push > 0.8 * stats.hz, 'the server pushes at its rate', `${stats.push.toFixed(2)} of ${stats.hz}/s`);
  check(stats.fps > 0, 'the page draws frames', `${stats.fps} fps`);
  // A scenario from the page: the C172 engine failure (its 10 s event is past: it fires at once),
  // confirmed by the engine's own report; stopped from the page before its `stop` ends the run.
  await page.selectOption('#form-scenario select[name=name]', 'c172_engine_failure.yaml');
  await page.click('#form-scenario button[name=start]');
  const failed = await waitFor('the scenario\'s failure confirmed', () => fedsim(() =>
    window.fedsim.state.commands.find((c) => c.text === 'fail engine1' && c.status !== 'pending')));
  check(failed.status === 'confirmed', 'a scenario run from the page fails the engine', failed.evidence);
  const fired = await fedsim(() => window.fedsim.state.scenario.fired);
  check(fired.some((f) => f.includes('fail engine1')), 'the page lists what the scenario did', fired.join(' | '));
  await page.click('#form-scenario button[name=stop]');
  await waitFor('the scenario stopped', () => fedsim(() => !window.fedsim.state.scenario.running));
  await page.selectOption('#form-failure select[name=system]', 'engine1');
  await page.click('#form-failure button[name=restore]');
  await waitFor('the engine restored', () => fedsim(() =>
    window.fedsim.state.commands.some((c) => c.text === 'restore engine1' && c.status === 'confirmed')));

  if (args.screenshot) {
    await page.screenshot({ path: args.screenshot, fullPage: true });
    console.log(`screenshot ${args.screenshot}`);
  }
} catch (e) {
  console.log('FAIL ' + e.message);
  failures++;
} finally {
  if (browser) await browser.close();
  federation.kill('SIGINT');
  const { code, signal } = await Promise.race([federationExit, sleep(30000).then(() => ({ code: 'timeout' }))]);
  if (code === 'timeout') federation.kill('SIGKILL');
  check(code === 0 || code === 130, 'the federation stops cleanly', `exit ${code} ${signal || ''}`);
  const log = fs.readFileSync(path.join(args.out, 'fedsim_run.log'), 'utf8');
  const summary = log.split('\n').find((l) => l.includes('fedsim-ios:') && l.includes('pushes'));
  if (summary) console.log(summary);
}
console.log(failures === 0 ? 'ios browser test: all checks passed' : `ios browser test: ${failures} check(s) failed`);
process.exit(failures === 0 ? 0 : 1);
