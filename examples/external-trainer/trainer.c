/* An external trainer: a fedsim federation member written in C against Eclipse Cyclone DDS,
 * from fedsim's own IDL (the .idl files of idl/, compiled unchanged by Cyclone's idlc). No fedsim code.
 *
 * What it does, each in a few lines below (docs/interop.md explains the rules it follows):
 *   - reads fedsim/aircraft_state and prints the ownship's state every --print-every frames;
 *   - writes fedsim/pilot_controls for aircraft --aircraft-id: the elevator held at --elevator
 *     (stamped with the tick's frame, so a lockstep run is reproducible);
 *   - writes one instructor command on fedsim/sim_command: --freeze-at-frame N (run state FREEZE);
 *   - is a lockstep member: announces itself on fedsim/federate_status and acknowledges every
 *     fedsim/frame_tick on fedsim/frame_done (liveliness rides on Cyclone's automatic leases).
 *
 * With --listen it only reads and prints (a monitor from another vendor's DDS: not a member).
 *
 * It stops on a SHUTDOWN command (fedsim run's timing federate sends one), SIGINT/SIGTERM, or
 * after --frames ticks. Options fedsim run passes to every member (--qos-file,
 * --participant-profile, --sync-qos) are accepted and ignored: Cyclone does not read Fast DDS
 * XML, and the QoS below match either sync mode.
 */
#include <dds/dds.h>

#include <errno.h>
#include <math.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "aircraft_state.h"
#include "command.h"
#include "controls.h"
#include "frame.h"
#include "status.h"

/* Loopback only, as fedsim's default participant profile (fedsim_loopback): discovery by
 * unicast to 127.0.0.1, participant indices 0..63 as Fast DDS uses them. CYCLONEDDS_URI, when
 * set, replaces this. */
static const char *kLoopbackConfig =
    "<CycloneDDS><Domain id=\"any\"><General><Interfaces>"
    "<NetworkInterface address=\"127.0.0.1\" multicast=\"false\"/>"
    "</Interfaces><AllowMulticast>false</AllowMulticast></General>"
    "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
    "<MaxAutoParticipantIndex>63</MaxAutoParticipantIndex>"
    "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery></Domain></CycloneDDS>";

struct options {
  const char *name;          /* federate name: must be in the timing federate's --expect list */
  int domain;                /* DDS domain id, 0..232 */
  int aircraft_id;           /* which aircraft the controls fly (0 = ownship) */
  double elevator;           /* held elevator, -1..1, + = stick forward */
  long long freeze_at_frame; /* send run state FREEZE at this frame; -1 = never */
  long long frames;          /* stop after this many ticks; 0 = until shutdown */
  long long print_every;     /* print the aircraft state every this many frames */
  int ownership_strength;    /* of the controls (EXCLUSIVE ownership): fedsim-io writes with 10 */
  int listen;                /* --listen: only read and print (no member, writes nothing) */
};

/* Federate names become file names and the timing federate's comma-separated --expect list. */
static const char *kNameCharacters = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789_-";

static volatile sig_atomic_t g_stop = 0;
static void on_signal(int sig) { (void)sig; g_stop = 1; }

static void usage_error(const char *what, const char *value) {
  fprintf(stderr, "external-trainer: %s: '%s'\n", what, value ? value : "(missing)");
  exit(2);
}

/* A number from the command line: finite, within [low, high], or exit with its name. */
static double number_arg(const char *option, const char *text, double low, double high) {
  char *end = NULL;
  errno = 0;
  const double v = text ? strtod(text, &end) : NAN;
  if (!text || end == text || *end != '\0' || errno != 0 || !isfinite(v) || v < low || v > high) {
    char what[160];
    snprintf(what, sizeof what, "%s needs a number in [%g, %g]", option, low, high);
    usage_error(what, text);
  }
  return v;
}

/* A whole number from the command line, within [low, high]. */
static long long whole_arg(const char *option, const char *text, double low, double high) {
  const double v = number_arg(option, text, low, high);
  if (v != floor(v)) {
    char what[160];
    snprintf(what, sizeof what, "%s needs a whole number", option);
    usage_error(what, text);
  }
  return (long long)v;
}

static struct options parse_options(int argc, char **argv) {
  struct options o = {"trainer", 0, 0, 0.0, -1, 0, 50, 20, 0};
  const char *env_domain = getenv("FEDSIM_DOMAIN");
  if (env_domain) o.domain = (int)whole_arg("FEDSIM_DOMAIN", env_domain, 0, 232);
  for (int i = 1; i < argc; ++i) {
    const char *opt = argv[i];
    const char *val = i + 1 < argc ? argv[i + 1] : NULL;
    if (!strcmp(opt, "--listen")) {
      o.listen = 1;
      continue; /* the only option without a value */
    }
    if (!strcmp(opt, "--name")) {
      const size_t n = val ? strlen(val) : 0;
      if (n < 1 || n > 32 || strspn(val, kNameCharacters) != n) {
        usage_error("--name needs 1-32 characters of A-Z a-z 0-9 _ -", val);
      }
      o.name = val;
    } else if (!strcmp(opt, "--domain")) {
      o.domain = (int)whole_arg(opt, val, 0, 232);
    } else if (!strcmp(opt, "--aircraft-id")) {
      o.aircraft_id = (int)whole_arg(opt, val, 0, 65535);
    } else if (!strcmp(opt, "--elevator")) {
      o.elevator = number_arg(opt, val, -1, 1);
    } else if (!strcmp(opt, "--freeze-at-frame")) {
      o.freeze_at_frame = whole_arg(opt, val, 0, 1e15);
    } else if (!strcmp(opt, "--frames")) {
      o.frames = whole_arg(opt, val, 0, 1e15);
    } else if (!strcmp(opt, "--print-every")) {
      o.print_every = whole_arg(opt, val, 1, 1e15);
    } else if (!strcmp(opt, "--ownership-strength")) {
      o.ownership_strength = (int)whole_arg(opt, val, 0, 2147483647);
    } else if (!strcmp(opt, "--qos-file") || !strcmp(opt, "--participant-profile") ||
               !strcmp(opt, "--sync-qos")) {
      if (!val) usage_error(opt, val); /* fedsim run's common options: see the top */
    } else {
      usage_error("unknown option", opt);
    }
    ++i; /* every option takes a value */
  }
  return o;
}

/* ---- QoS: each as docs/interop.md's table (qos/fedsim_qos.xml) ------------------------------ */

static dds_qos_t *base_qos(dds_reliability_kind_t reliability, dds_durability_kind_t durability,
                           int32_t depth) {
  dds_qos_t *q = dds_create_qos();
  dds_qset_reliability(q, reliability, DDS_MSECS(100));
  dds_qset_durability(q, durability);
  dds_qset_history(q, DDS_HISTORY_KEEP_LAST, depth);
  /* fedsim's types are final: plain CDR (XCDR1). XCDR2 matches Fast DDS 2.9 but delivers nothing. */
  dds_qset_data_representation(q, 1, (dds_data_representation_id_t[]){DDS_DATA_REPRESENTATION_XCDR1});
  return q;
}

static dds_entity_t must(dds_entity_t e, const char *what) {
  if (e < 0) {
    fprintf(stderr, "external-trainer: %s failed: %s\n", what, dds_strretcode(e));
    exit(1);
  }
  return e;
}

static dds_entity_t topic(dds_entity_t pp, const dds_topic_descriptor_t *type, const char *name) {
  return must(dds_create_topic(pp, type, name, NULL, NULL), name);
}

/* Before creating any writer: fedsim readers of per-frame topics report a matched writer that
 * writes nothing for --silent-frames frames (fault silent_writer), so a late joiner must not
 * match before its ticks flow. Discovery is two-sided: hearing the timing federate's writer does
 * not mean it hears us yet. So: wait for its tick writer, then up to 1 s for a tick. A tick means
 * the federation is already running (we are a late joiner, and now ticks reach us); none means it
 * is still assembling (a lockstep federation waits for our READY). */
static void wait_for_ticks_to_flow(dds_entity_t ticks) {
  dds_subscription_matched_status_t matched = {0};
  for (int i = 0; i < 1000 && !g_stop && matched.current_count == 0; ++i) { /* 10 s at most */
    dds_get_subscription_matched_status(ticks, &matched);
    dds_sleepfor(DDS_MSECS(10));
  }
  if (matched.current_count == 0) {
    fprintf(stderr, "external-trainer: no fedsim/frame_tick writer after 10 s (is fedsim-timing up?)\n");
  }
  for (int i = 0; i < 100 && !g_stop; ++i) {
    void *ptr[1] = {NULL};
    dds_sample_info_t info[1];
    if (dds_take(ticks, ptr, info, 1, 1) > 0) { /* not answered: we are no member of its frame */
      dds_return_loan(ticks, ptr, 1);
      return;
    }
    dds_sleepfor(DDS_MSECS(10));
  }
}

/* A writer, except when only listening (no writer then: nothing to match, nothing written). */
static dds_entity_t writer(int listen, dds_entity_t pp, dds_entity_t t, const dds_qos_t *q, const char *what) {
  return listen ? 0 : must(dds_create_writer(pp, t, q, NULL), what);
}

/* ---- The lockstep member contract --------------------------------------------------------- */

struct member {
  dds_entity_t status_writer, done_writer;
  fedsim_msg_FederateStatus status;
  fedsim_msg_FrameDone done;
  int listening; /* --listen: never announces itself */
};

static void publish_status(struct member *m, fedsim_msg_FederateState state, uint64_t frames,
                           const char *message) {
  if (m->listening) return;
  m->status.state = state;
  m->status.frames_done = frames;
  snprintf(m->status.message, sizeof m->status.message, "%s", message);
  dds_write(m->status_writer, &m->status);
}

static void acknowledge(struct member *m, uint64_t frame) {
  m->done.frame = frame;
  dds_write(m->done_writer, &m->done);
}

/* ---- One pass of the frame loop ------------------------------------------------------------ */

struct trainer {
  struct options o;
  struct member m;
  dds_entity_t ticks, commands, states, command_writer, controls_writer;
  fedsim_msg_PilotControls controls;
  uint64_t last_acked, frames_done;
  int acked_any, frozen_sent;
  const char *stop_reason;
};

/* Commands: only SHUTDOWN concerns this program (the timing federate sends it at the end). */
static void take_commands(struct trainer *t) {
  void *ptr[1] = {NULL};
  dds_sample_info_t info[1];
  while (dds_take(t->commands, ptr, info, 1, 1) > 0) {
    const fedsim_msg_SimCommand *cmd = ptr[0];
    if (info[0].valid_data && cmd->kind == fedsim_msg_COMMAND_SHUTDOWN) {
      g_stop = 1;
      t->stop_reason = "shutdown command";
    }
    dds_return_loan(t->commands, ptr, 1);
    ptr[0] = NULL; /* the next take lends again */
  }
}

/* Aircraft state: print our aircraft's samples of every --print-every'th frame. */
static void print_states(struct trainer *t) {
  void *ptr[1] = {NULL};
  dds_sample_info_t info[1];
  while (dds_take(t->states, ptr, info, 1, 1) > 0) {
    const fedsim_msg_AircraftState *s = ptr[0];
    if (info[0].valid_data && s->aircraft_id == t->o.aircraft_id && s->stamp.frame % t->o.print_every == 0) {
      printf("state frame=%llu sim_time_s=%.3f altitude_msl_m=%.3f theta_deg=%.3f tas_mps=%.3f\n",
             (unsigned long long)s->stamp.frame, s->stamp.sim_time_s, s->altitude_msl_m,
             s->theta_rad * 57.29577951308232, s->air.tas_mps);
    }
    dds_return_loan(t->states, ptr, 1);
    ptr[0] = NULL; /* the next take lends again */
  }
}

/* The instructor command of this example: run state FREEZE (applied by the timing federate). */
static void send_freeze(struct trainer *t, uint64_t frame) {
  fedsim_msg_SimCommand freeze;
  memset(&freeze, 0, sizeof freeze);
  freeze.kind = fedsim_msg_COMMAND_RUN_STATE; /* key: kind and target ("" = everyone) */
  freeze.run_state = fedsim_msg_RUN_STATE_FREEZE;
  freeze.sequence_number = 1;
  snprintf(freeze.issuer, sizeof freeze.issuer, "%s", t->o.name);
  dds_write(t->command_writer, &freeze);
  t->frozen_sent = 1;
  printf("command freeze sent at frame=%llu\n", (unsigned long long)frame);
}

/* A new frame: write its outputs stamped with the tick, then acknowledge it. */
static void step(struct trainer *t, const fedsim_msg_FrameTick *tick) {
  if (t->o.freeze_at_frame >= 0 && (long long)tick->frame >= t->o.freeze_at_frame && !t->frozen_sent) {
    send_freeze(t, tick->frame);
  }
  t->controls.stamp.frame = tick->frame; /* the flight federate flies it in frame + 1 */
  t->controls.stamp.sim_time_s = tick->sim_time_s;
  t->controls.elevator = (float)t->o.elevator;
  dds_write(t->controls_writer, &t->controls);
  acknowledge(&t->m, tick->frame);
  if (!t->acked_any) publish_status(&t->m, fedsim_msg_FEDERATE_RUNNING, 1, "");
  t->acked_any = 1;
  t->last_acked = tick->frame;
  ++t->frames_done;
  if (t->o.frames > 0 && (long long)t->frames_done >= t->o.frames) {
    g_stop = 1;
    t->stop_reason = "--frames reached";
  }
}

/* Ticks: a new frame is stepped; a repeated one (the timing federate resends a tick whose
 * acknowledgement went missing) is acknowledged again, not stepped; an older one is ignored. */
static void answer_ticks(struct trainer *t) {
  void *ptr[1] = {NULL};
  dds_sample_info_t info[1];
  while (!g_stop && dds_take(t->ticks, ptr, info, 1, 1) > 0) {
    const fedsim_msg_FrameTick tick = *(const fedsim_msg_FrameTick *)ptr[0];
    const int valid = info[0].valid_data;
    dds_return_loan(t->ticks, ptr, 1);
    ptr[0] = NULL; /* the next take lends again */
    if (!valid || t->o.listen || (t->acked_any && tick.frame < t->last_acked)) continue;
    if (t->acked_any && tick.frame == t->last_acked) {
      acknowledge(&t->m, tick.frame);
    } else {
      step(t, &tick);
    }
  }
}

int main(int argc, char **argv) {
  struct trainer t;
  memset(&t, 0, sizeof t);
  t.o = parse_options(argc, argv);
  const struct options o = t.o;
  t.stop_reason = "signal";
  setvbuf(stdout, NULL, _IOLBF, 0); /* line by line into fedsim run's log */
  signal(SIGINT, on_signal);
  signal(SIGTERM, on_signal);

  if (!getenv("CYCLONEDDS_URI")) must(dds_create_domain(o.domain, kLoopbackConfig), "domain");
  const dds_entity_t pp = must(dds_create_participant(o.domain, NULL, NULL), "participant");

  /* Backbone: tick (best effort reader: matches a best-effort or reliable tick writer). */
  dds_qos_t *q = base_qos(DDS_RELIABILITY_BEST_EFFORT, DDS_DURABILITY_VOLATILE, 1);
  t.ticks = must(
      dds_create_reader(pp, topic(pp, &fedsim_msg_FrameTick_desc, fedsim_msg_TOPIC_FRAME_TICK), q, NULL),
      "tick reader");
  dds_delete_qos(q);
  if (!o.listen) wait_for_ticks_to_flow(t.ticks);

  /* Acknowledgement: reliable (matches either sync mode), liveliness lease <= the 1.5 s the
   * timing federate requests; keyed by federate name. */
  struct member *m = &t.m;
  m->listening = o.listen;
  q = base_qos(DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_VOLATILE, 1);
  dds_qset_liveliness(q, DDS_LIVELINESS_AUTOMATIC, DDS_MSECS(1500));
  m->done_writer = writer(o.listen, pp, topic(pp, &fedsim_msg_FrameDone_desc, fedsim_msg_TOPIC_FRAME_DONE),
                          q, "frame_done writer");
  dds_delete_qos(q);
  snprintf(m->done.federate, sizeof m->done.federate, "%s", o.name);

  /* Status: reliable, transient local, liveliness lease <= 2 s. */
  q = base_qos(DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_TRANSIENT_LOCAL, 1);
  dds_qset_liveliness(q, DDS_LIVELINESS_AUTOMATIC, DDS_SECS(2));
  m->status_writer = writer(o.listen, pp,
                            topic(pp, &fedsim_msg_FederateStatus_desc, fedsim_msg_TOPIC_FEDERATE_STATUS),
                            q, "status writer");
  dds_delete_qos(q);
  snprintf(m->status.federate, sizeof m->status.federate, "%s", o.name);
  snprintf(m->status.host, sizeof m->status.host, "external");
  m->status.pid = (uint32_t)getpid();

  /* Commands: reliable, transient local, keep last 1 (per kind and target). */
  q = base_qos(DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_TRANSIENT_LOCAL, 1);
  const dds_entity_t command_topic = topic(pp, &fedsim_msg_SimCommand_desc, fedsim_msg_TOPIC_SIM_COMMAND);
  t.command_writer = writer(o.listen, pp, command_topic, q, "command writer");
  t.commands = must(dds_create_reader(pp, command_topic, q, NULL), "command reader");
  dds_delete_qos(q);

  /* Pilot controls: reliable, transient local, keep last 2, EXCLUSIVE ownership (one owner per
   * aircraft: the strongest live writer; 20 outranks fedsim-io's 10). */
  q = base_qos(DDS_RELIABILITY_RELIABLE, DDS_DURABILITY_TRANSIENT_LOCAL, 2);
  dds_qset_ownership(q, DDS_OWNERSHIP_EXCLUSIVE);
  dds_qset_ownership_strength(q, o.ownership_strength);
  t.controls_writer = writer(o.listen, pp, topic(pp, &fedsim_msg_PilotControls_desc, fedsim_msg_TOPIC_PILOT_CONTROLS),
                             q, "pilot_controls writer");
  dds_delete_qos(q);
  t.controls.aircraft_id = (uint16_t)o.aircraft_id;
  t.controls.gear_down = true; /* everything else 0: centred, and relative to trim in relative mode */

  /* Aircraft state: a best-effort reader matches both "state" and "lockstep_data" writers. It
   * keeps the last 16 samples (a local setting) so that none is lost between two wake-ups. */
  q = base_qos(DDS_RELIABILITY_BEST_EFFORT, DDS_DURABILITY_VOLATILE, 16);
  t.states = must(
      dds_create_reader(pp, topic(pp, &fedsim_msg_AircraftState_desc, fedsim_msg_TOPIC_AIRCRAFT_STATE), q, NULL),
      "aircraft_state reader");
  dds_delete_qos(q);

  /* Ready: the timing federate starts ticking once every expected member said so. */
  publish_status(m, fedsim_msg_FEDERATE_READY, 0, "");
  printf("external-trainer: %s ready on domain %d\n", o.name, o.domain);

  const dds_entity_t waitset = dds_create_waitset(pp);
  dds_waitset_attach(waitset, dds_create_readcondition(t.ticks, DDS_ANY_STATE), 0);
  dds_waitset_attach(waitset, dds_create_readcondition(t.commands, DDS_ANY_STATE), 0);
  dds_time_t next_status = dds_time() + DDS_SECS(1);
  while (!g_stop) {
    dds_waitset_wait(waitset, NULL, 0, DDS_MSECS(100));
    take_commands(&t);
    print_states(&t);
    answer_ticks(&t);
    if (dds_time() >= next_status) { /* heartbeat: the status once a second, with the frame count */
      next_status += DDS_SECS(1);
      publish_status(m, t.acked_any ? fedsim_msg_FEDERATE_RUNNING : fedsim_msg_FEDERATE_READY, t.frames_done, "");
    }
  }

  publish_status(m, fedsim_msg_FEDERATE_STOPPING, t.frames_done, t.stop_reason);
  if (!o.listen) { /* reliable samples still in flight reach their readers before the participant goes */
    dds_wait_for_acks(m->status_writer, DDS_SECS(1));
    dds_wait_for_acks(t.controls_writer, DDS_SECS(1));
  }
  /* fedsim's timing federate waits for every reader to acknowledge its (reliable) SHUTDOWN:
   * stay one of its heartbeat periods (0.1 s) longer, so that the acknowledgement goes out. */
  dds_sleepfor(DDS_MSECS(300));
  printf("external-trainer: stopping reason=\"%s\" frames=%llu\n", t.stop_reason,
         (unsigned long long)t.frames_done);
  dds_delete(pp);
  return 0;
}
