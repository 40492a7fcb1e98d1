/* A small FMI 2.0 host of the project's own: loads the law and gear FMUs (unpacked archives)
 * with dlopen and drives the C API directly, as an importing tool does, and checks
 *  - the law: outputs against properties that hold for every patch (dissipation F.v + Mz w <= 0,
 *    linearity in N, Model Exchange = Co-Simulation), the directional derivatives against
 *    central differences of the outputs;
 *  - bad inputs (NaN, a negative load, a wrong guid, a missing or damaged resource, calls out of
 *    order, an output set, an unknown value reference): fmi2Error or NULL with a logger message
 *    naming the problem, never a crash;
 *  - several instances in threads: the same numbers as one after another;
 *  - the gear: a landing stepped to 0.4 s, a bad parameter refused at initialisation, and two
 *    instances in threads.
 * Usage: fmu_host LAW_DIR GEAR_DIR WORK_DIR (the unpacked .fmu folders; WORK_DIR for damaged
 * copies). Prints "N passed, N failed" and exits 1 on a failure. */
#include <dlfcn.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>

#include "fmi2Functions.h"

static int passed = 0, failed = 0;

#define CHECK(cond, ...)                          \
  do {                                            \
    if (cond) {                                   \
      ++passed;                                   \
    } else {                                      \
      ++failed;                                   \
      printf("FAIL %s:%d: ", __FILE__, __LINE__); \
      printf(__VA_ARGS__);                        \
      printf("\n");                               \
    }                                             \
  } while (0)

typedef struct {
  void* lib;
  fmi2InstantiateTYPE* instantiate;
  fmi2FreeInstanceTYPE* free_instance;
  fmi2SetupExperimentTYPE* setup;
  fmi2EnterInitializationModeTYPE* enter_init;
  fmi2ExitInitializationModeTYPE* exit_init;
  fmi2TerminateTYPE* terminate;
  fmi2ResetTYPE* reset;
  fmi2GetRealTYPE* get_real;
  fmi2SetRealTYPE* set_real;
  fmi2SetStringTYPE* set_string;
  fmi2DoStepTYPE* do_step;
  fmi2GetDirectionalDerivativeTYPE* derivative;
  fmi2EnterContinuousTimeModeTYPE* continuous;
  fmi2NewDiscreteStatesTYPE* new_discrete;
  fmi2SetTimeTYPE* set_time;
  char guid[64];
  char resources[4096];
} Fmu;

/* What the logger last said to one instance (componentEnvironment points here). */
typedef struct {
  char message[2048];
  fmi2Status status;
} Log;

static void logger(fmi2ComponentEnvironment env, fmi2String name, fmi2Status status,
                   fmi2String category, fmi2String format, ...) {
  Log* log = (Log*)env;
  va_list args;
  va_start(args, format);
  vsnprintf(log->message, sizeof log->message, format, args);
  va_end(args);
  log->status = status;
  (void)name;
  (void)category;
}

static void* symbol(void* lib, const char* name) {
  void* p = dlsym(lib, name);
  if (!p) {
    printf("FAIL: %s not exported\n", name);
    exit(1);
  }
  return p;
}

static char* read_file(const char* path) {
  FILE* f = fopen(path, "rb");
  if (!f) return NULL;
  fseek(f, 0, SEEK_END);
  long n = ftell(f);
  fseek(f, 0, SEEK_SET);
  char* text = malloc((size_t)n + 1);
  size_t got = fread(text, 1, (size_t)n, f);
  text[got] = 0;
  fclose(f);
  return text;
}

/* The value reference of a variable, from modelDescription.xml. */
static unsigned reference(const char* dir, const char* name) {
  char path[4096], key[256];
  snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
  char* xml = read_file(path);
  snprintf(key, sizeof key, "name=\"%s\" valueReference=\"", name);
  char* at = xml ? strstr(xml, key) : NULL;
  unsigned vr = at ? (unsigned)strtoul(at + strlen(key), NULL, 10) : 0xFFFFFFFFu;
  free(xml);
  if (vr == 0xFFFFFFFFu) {
    printf("FAIL: no variable %s in %s\n", name, path);
    exit(1);
  }
  return vr;
}

static void load(Fmu* f, const char* dir, const char* id) {
  char path[4096];
  snprintf(path, sizeof path, "%s/binaries/linux64/%s.so", dir, id);
  f->lib = dlopen(path, RTLD_NOW | RTLD_LOCAL);
  if (!f->lib) {
    printf("FAIL: dlopen %s: %s\n", path, dlerror());
    exit(1);
  }
  f->instantiate = (fmi2InstantiateTYPE*)symbol(f->lib, "fmi2Instantiate");
  f->free_instance = (fmi2FreeInstanceTYPE*)symbol(f->lib, "fmi2FreeInstance");
  f->setup = (fmi2SetupExperimentTYPE*)symbol(f->lib, "fmi2SetupExperiment");
  f->enter_init = (fmi2EnterInitializationModeTYPE*)symbol(f->lib, "fmi2EnterInitializationMode");
  f->exit_init = (fmi2ExitInitializationModeTYPE*)symbol(f->lib, "fmi2ExitInitializationMode");
  f->terminate = (fmi2TerminateTYPE*)symbol(f->lib, "fmi2Terminate");
  f->reset = (fmi2ResetTYPE*)symbol(f->lib, "fmi2Reset");
  f->get_real = (fmi2GetRealTYPE*)symbol(f->lib, "fmi2GetReal");
  f->set_real = (fmi2SetRealTYPE*)symbol(f->lib, "fmi2SetReal");
  f->set_string = (fmi2SetStringTYPE*)symbol(f->lib, "fmi2SetString");
  f->do_step = (fmi2DoStepTYPE*)symbol(f->lib, "fmi2DoStep");
  f->derivative = (fmi2GetDirectionalDerivativeTYPE*)symbol(f->lib, "fmi2GetDirectionalDerivative");
  f->continuous = (fmi2EnterContinuousTimeModeTYPE*)symbol(f->lib, "fmi2EnterContinuousTimeMode");
  f->new_discrete = (fmi2NewDiscreteStatesTYPE*)symbol(f->lib, "fmi2NewDiscreteStates");
  f->set_time = (fmi2SetTimeTYPE*)symbol(f->lib, "fmi2SetTime");
  snprintf(path, sizeof path, "%s/modelDescription.xml", dir);
  char* xml = read_file(path);
  char* g = xml ? strstr(xml, "guid=\"") : NULL;
  if (!g) {
    printf("FAIL: no guid in %s\n", path);
    exit(1);
  }
  g += 6;
  size_t n = (size_t)(strchr(g, '"') - g);
  memcpy(f->guid, g, n < sizeof f->guid ? n : sizeof f->guid - 1);
  free(xml);
  snprintf(f->resources, sizeof f->resources, "file://%s/resources", dir);
}

static fmi2Component instance(const Fmu* f, fmi2Type type, Log* log, const char* guid,
                              const char* resources) {
  fmi2CallbackFunctions cb = {logger, calloc, free, NULL, log};
  log->message[0] = 0;
  return f->instantiate("host", type, guid ? guid : f->guid, resources ? resources : f->resources,
                        &cb, fmi2False, fmi2False);
}

/* Instantiated and initialised (start time 0), or NULL. */
static fmi2Component ready(const Fmu* f, fmi2Type type, Log* log) {
  fmi2Component c = instance(f, type, log, NULL, NULL);
  if (!c) return NULL;
  if (f->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0) != fmi2OK || f->enter_init(c) != fmi2OK ||
      f->exit_init(c) != fmi2OK) {
    f->free_instance(c);
    return NULL;
  }
  if (type == fmi2ModelExchange) {
    fmi2EventInfo info;
    f->new_discrete(c, &info);
    f->continuous(c);
  }
  return c;
}

static const fmi2ValueReference kInputs[4] = {0, 1, 2, 3}, kOutputs[3] = {4, 5, 6};

static int outputs(const Fmu* f, fmi2Component c, const double in[4], double out[3]) {
  if (f->set_real(c, kInputs, 4, in) != fmi2OK) return 0;
  return f->get_real(c, kOutputs, 3, out) == fmi2OK;
}

static double frand(unsigned* s) {
  *s = *s * 1103515245u + 12345u;
  return ((*s >> 8) & 0xFFFFFF) / 16777216.0;
}

/* Random kinematics over the regimes: pure spin, pure sliding, both, rest. */
static void kinematics(unsigned* s, double in[4]) {
  const int kind = (int)(frand(s) * 4.0);
  const double v = pow(10.0, -3.0 + 4.0 * frand(s)), a = 6.283185307179586 * frand(s);
  in[0] = kind == 0 ? 0.0 : v * cos(a);
  in[1] = kind == 0 ? 0.0 : v * sin(a);
  in[2] = kind == 1 ? 0.0 : (frand(s) - 0.5) * 40.0;
  in[3] = 100.0 + 9000.0 * frand(s);
  if (kind == 3) in[0] = in[1] = in[2] = 0.0;
}

static void law_properties(const Fmu* f) {
  Log log;
  fmi2Component cs = ready(f, fmi2CoSimulation, &log), me = ready(f, fmi2ModelExchange, &log);
  CHECK(cs && me, "instantiation failed: %s", log.message);
  if (!cs || !me) return;
  unsigned seed = 7;
  double worst_power = 0.0, worst_linear = 0.0, worst_jac = 0.0, worst_me = 0.0;
  for (int i = 0; i < 400; ++i) {
    double in[4], out[3], out2[3], out_me[3];
    kinematics(&seed, in);
    CHECK(outputs(f, cs, in, out), "outputs failed: %s", log.message);
    CHECK(f->do_step(cs, i * 1e-3, 1e-3, fmi2True) == fmi2OK, "doStep: %s", log.message);
    f->set_time(me, i * 1e-3);
    CHECK(outputs(f, me, in, out_me), "ME outputs failed: %s", log.message);
    const double fN = 0.3 * in[3], scale = fN * (1.0 + 0.087);
    for (int k = 0; k < 3; ++k) worst_me = fmax(worst_me, fabs(out[k] - out_me[k]) / scale);
    /* F.v + Mz omega <= 0 (friction dissipates). */
    const double power = out[0] * in[0] + out[1] * in[1] + out[2] * in[2];
    const double speed = fabs(in[0]) + fabs(in[1]) + fabs(in[2]) * 0.087;
    worst_power = fmax(worst_power, power / (fN * speed + 1e-300));
    double twice[4] = {in[0], in[1], in[2], 2.0 * in[3]};
    CHECK(outputs(f, cs, twice, out2), "outputs failed: %s", log.message);
    for (int k = 0; k < 3; ++k)
      worst_linear = fmax(worst_linear, fabs(out2[k] - 2.0 * out[k]) / scale);
    /* Directional derivatives against central differences (away from rest and pure spin,
     * where the law has kinks). */
    if (speed > 1e-2 && fabs(in[0]) + fabs(in[1]) > 1e-2) {
      for (unsigned j = 0; j < 4; ++j) {
        const double h = j < 3 ? 1e-6 * speed / (j == 2 ? 0.087 : 1.0) : 1e-3 * in[3];
        double plus[4], minus[4], op[3], om[3], d[3], one = 1.0;
        memcpy(plus, in, sizeof plus);
        memcpy(minus, in, sizeof minus);
        plus[j] += h;
        minus[j] -= h;
        outputs(f, cs, plus, op);
        outputs(f, cs, minus, om);
        outputs(f, cs, in, out2);
        const fmi2ValueReference known = j;
        CHECK(f->derivative(cs, kOutputs, 3, &known, 1, &one, d) == fmi2OK, "derivative: %s",
              log.message);
        for (int k = 0; k < 3; ++k) {
          const double fd = (op[k] - om[k]) / (2.0 * h);
          const double unit = j < 3 ? scale / speed * (j == 2 ? 0.087 : 1.0) : scale / in[3];
          worst_jac = fmax(worst_jac, fabs(fd - d[k]) / unit);
        }
      }
    }
  }
  CHECK(worst_power <= 1e-12, "dissipation: F.v + Mz w = %g f N |v|", worst_power);
  CHECK(worst_linear <= 1e-14, "linear in N: %g", worst_linear);
  CHECK(worst_me <= 0.0, "Model Exchange and Co-Simulation differ by %g", worst_me);
  CHECK(worst_jac <= 1e-4, "directional derivatives off the differences by %g", worst_jac);
  printf("law: 400 random kinematics, dissipation %.1e, linearity %.1e, derivatives %.1e\n",
         worst_power, worst_linear, worst_jac);
  f->terminate(cs);
  f->free_instance(cs);
  f->free_instance(me);
}

/* A call refused with fmi2Error and a logged message containing `word`. */
#define REFUSED(call, word)                                                                   \
  do {                                                                                        \
    log.message[0] = 0;                                                                       \
    const fmi2Status s_ = (call);                                                             \
    CHECK(s_ == fmi2Error && strstr(log.message, word), "%s: status %d, message '%s'", #call, \
          (int)s_, log.message);                                                              \
  } while (0)

static void law_bad_inputs(const Fmu* f, const char* work) {
  Log log;
  fmi2Component c = instance(f, fmi2CoSimulation, &log, NULL, NULL);
  CHECK(c != NULL, "instantiate: %s", log.message);
  const double nan = NAN, negative = -5.0, one = 1.0;
  const fmi2ValueReference vx = 0, load = 3, fx = 4, bad = 99;
  double out;
  REFUSED(f->do_step(c, 0.0, 1e-3, fmi2True), "not allowed");
  f->reset(c);
  REFUSED(f->get_real(c, &fx, 1, &out), "not allowed");
  f->reset(c);
  f->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->set_real(c, &vx, 1, &nan), "vx");
  REFUSED(f->get_real(c, &fx, 1, &out), "earlier error"); /* the failed state */
  CHECK(f->reset(c) == fmi2OK, "reset after an error: %s", log.message);
  f->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->set_real(c, &load, 1, &negative), "N = -5");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->set_real(c, &fx, 1, &one), "cannot be set");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->get_real(c, &bad, 1, &out), "no such variable");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  f->terminate(c); /* terminated: values can be read, not set (FMI 2.0, section 4.3.1) */
  CHECK(f->get_real(c, &fx, 1, &out) == fmi2OK, "get after terminate: %s", log.message);
  REFUSED(f->set_real(c, &vx, 1, &one), "not allowed");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->do_step(c, 5.0, 1e-3, fmi2True), "end of the previous step");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->do_step(c, 0.0, -1.0, fmi2True), "communicationStepSize");
  f->reset(c);
  f->enter_init(c);
  f->exit_init(c);
  REFUSED(f->get_real(c, NULL, 1, &out), "vr");
  f->free_instance(c);
  f->free_instance(NULL); /* a no-op */
  CHECK(f->do_step(NULL, 0.0, 1e-3, fmi2True) == fmi2Error, "doStep on NULL");

  /* Instantiation refused: wrong guid, missing resource, damaged resource, no callbacks. */
  c = instance(f, fmi2CoSimulation, &log, "{00000000-0000-0000-0000-000000000000}", NULL);
  CHECK(!c && strstr(log.message, "guid"), "wrong guid: '%s'", log.message);
  char path[4096], uri[4200];
  snprintf(path, sizeof path, "%s/empty", work);
  mkdir(path, 0755);
  snprintf(uri, sizeof uri, "file://%s", path);
  c = instance(f, fmi2CoSimulation, &log, NULL, uri);
  CHECK(!c && strstr(log.message, "cannot read"), "missing resource: '%s'", log.message);
  snprintf(path, sizeof path, "%s/damaged", work);
  mkdir(path, 0755);
  char source[4200], target[4200];
  snprintf(source, sizeof source, "%s/law.txt", f->resources + 7);
  snprintf(target, sizeof target, "%s/law.txt", path);
  char* text = read_file(source);
  FILE* out_file = fopen(target, "wb");
  fwrite(text, 1, strlen(text) * 2 / 3, out_file); /* cut in the middle of the tables */
  fclose(out_file);
  free(text);
  snprintf(uri, sizeof uri, "file://%s", path);
  c = instance(f, fmi2CoSimulation, &log, NULL, uri);
  CHECK(!c && strstr(log.message, "law.txt:"), "damaged resource: '%s'", log.message);
  c = instance(f, fmi2CoSimulation, &log, NULL, "http://example.org/resources");
  CHECK(!c && strstr(log.message, "file:"), "remote resource: '%s'", log.message);
  c = f->instantiate("host", fmi2CoSimulation, f->guid, f->resources, NULL, fmi2False, fmi2False);
  CHECK(!c, "no callbacks");
  c = instance(f, (fmi2Type)7, &log, NULL, NULL);
  CHECK(!c && strstr(log.message, "fmuType"), "bad fmuType: '%s'", log.message);
  printf("law: bad inputs and calls refused with messages\n");
}

/* Several instances in threads: each steps its own sequence; the results must be those of
 * the same sequences run one after another. */
typedef struct {
  const Fmu* fmu;
  unsigned seed;
  double sum[3];
  int ok;
} LawJob;

static void* law_job(void* p) {
  LawJob* job = (LawJob*)p;
  Log log;
  fmi2Component c = ready(job->fmu, fmi2CoSimulation, &log);
  job->ok = c != NULL;
  unsigned seed = job->seed;
  for (int i = 0; c && i < 3000; ++i) {
    double in[4], out[3];
    kinematics(&seed, in);
    job->ok &= outputs(job->fmu, c, in, out);
    job->ok &= job->fmu->do_step(c, i * 1e-3, 1e-3, fmi2True) == fmi2OK;
    for (int k = 0; k < 3; ++k) job->sum[k] += out[k] * (1.0 + 1e-3 * i);
  }
  if (c) job->fmu->free_instance(c);
  return NULL;
}

static void law_threads(const Fmu* f) {
  enum { kJobs = 4 };
  LawJob serial[kJobs], parallel[kJobs];
  pthread_t threads[kJobs];
  for (int j = 0; j < kJobs; ++j) {
    serial[j] = (LawJob){f, 11u + 7u * (unsigned)j, {0, 0, 0}, 0};
    parallel[j] = serial[j];
    law_job(&serial[j]);
  }
  for (int j = 0; j < kJobs; ++j) pthread_create(&threads[j], NULL, law_job, &parallel[j]);
  for (int j = 0; j < kJobs; ++j) pthread_join(threads[j], NULL);
  for (int j = 0; j < kJobs; ++j) {
    CHECK(serial[j].ok && parallel[j].ok, "job %d failed", j);
    for (int k = 0; k < 3; ++k)
      CHECK(serial[j].sum[k] == parallel[j].sum[k], "job %d: threads %.17g, serial %.17g", j,
            parallel[j].sum[k], serial[j].sum[k]);
  }
  printf("law: %d instances in threads, 3000 steps each, the same as one after another\n", kJobs);
}

typedef struct {
  const Fmu* fmu;
  const char* dir;
  double offset;
  double psi_peak, psi_end;
  int ok;
  char message[2048];
} GearJob;

static void* gear_job(void* p) {
  GearJob* job = (GearJob*)p;
  const Fmu* f = job->fmu;
  Log log;
  fmi2Component c = instance(f, fmi2CoSimulation, &log, NULL, NULL);
  job->ok = c != NULL;
  if (!c) {
    snprintf(job->message, sizeof job->message, "%s", log.message);
    return NULL;
  }
  const fmi2ValueReference offset = reference(job->dir, "structure.offset_m"),
                           brake = reference(job->dir, "brake_torque_command_nm"),
                           psi = reference(job->dir, "psi_rad");
  f->set_real(c, &offset, 1, &job->offset);
  f->setup(c, fmi2False, 0.0, 0.0, fmi2False, 0.0);
  f->enter_init(c);
  job->ok = f->exit_init(c) == fmi2OK;
  const double dt = 5e-4, torque = 40e3;
  for (int i = 0; job->ok && i < 800; ++i) {
    if (i == 500) job->ok &= f->set_real(c, &brake, 1, &torque) == fmi2OK; /* brake at 0.25 s */
    job->ok &= f->do_step(c, i * dt, dt, fmi2True) == fmi2OK;
    double value = 0.0;
    job->ok &= f->get_real(c, &psi, 1, &value) == fmi2OK;
    job->psi_peak = fmax(job->psi_peak, fabs(value));
    job->psi_end = value;
  }
  snprintf(job->message, sizeof job->message, "%s", log.message);
  f->free_instance(c);
  return NULL;
}

static void gear(const Fmu* f, const char* dir) {
  GearJob serial[2] = {{f, dir, 0.25, 0, 0, 0, ""}, {f, dir, 0.35, 0, 0, 0, ""}}, parallel[2];
  pthread_t threads[2];
  for (int j = 0; j < 2; ++j) {
    parallel[j] = serial[j];
    gear_job(&serial[j]);
    CHECK(serial[j].ok && isfinite(serial[j].psi_end) && serial[j].psi_peak > 0.0 &&
              serial[j].psi_peak < 0.5,
          "gear run %d: ok %d, peak torsion %g rad: %s", j, serial[j].ok, serial[j].psi_peak,
          serial[j].message);
  }
  for (int j = 0; j < 2; ++j) pthread_create(&threads[j], NULL, gear_job, &parallel[j]);
  for (int j = 0; j < 2; ++j) pthread_join(threads[j], NULL);
  for (int j = 0; j < 2; ++j)
    CHECK(parallel[j].ok && parallel[j].psi_end == serial[j].psi_end &&
              parallel[j].psi_peak == serial[j].psi_peak,
          "gear run %d in a thread: %.17g, serial %.17g", j, parallel[j].psi_end,
          serial[j].psi_end);
  CHECK(serial[0].psi_end != serial[1].psi_end, "the offset parameter changed nothing");
  printf("gear: two landings to 0.4 s (peak torsion %.3g, %.3g rad), the same in threads\n",
         serial[0].psi_peak, serial[1].psi_peak);

  Log log;
  fmi2Component c = instance(f, fmi2CoSimulation, &log, NULL, NULL);
  const fmi2ValueReference mass = reference(dir, "structure.lateral_mass_kg"),
                           speed = reference(dir, "forward_speed_mps"),
                           model = reference(dir, "contact_model");
  const double negative = -300.0, nan = NAN;
  f->set_real(c, &mass, 1, &negative);
  f->enter_init(c);
  REFUSED(f->exit_init(c), "structure.lateral_mass_kg");
  f->reset(c);
  REFUSED(f->set_real(c, &speed, 1, &nan), "forward_speed_mps");
  f->reset(c);
  const char* name = "bogus";
  f->set_string(c, &model, 1, &name);
  f->enter_init(c);
  REFUSED(f->exit_init(c), "bogus");
  f->free_instance(c);
  c = instance(f, fmi2ModelExchange, &log, NULL, NULL);
  CHECK(!c && strstr(log.message, "Co-Simulation"), "gear as ME: '%s'", log.message);
  printf("gear: bad parameters and inputs refused with messages\n");
}

int main(int argc, char** argv) {
  if (argc != 4) {
    fprintf(stderr, "usage: fmu_host LAW_DIR GEAR_DIR WORK_DIR\n");
    return 2;
  }
  Fmu law, gear_fmu;
  memset(&law, 0, sizeof law);
  memset(&gear_fmu, 0, sizeof gear_fmu);
  load(&law, argv[1], "contensou_law");
  law_properties(&law);
  law_bad_inputs(&law, argv[3]);
  law_threads(&law);
  load(&gear_fmu, argv[2], "contensou_gear");
  gear(&gear_fmu, argv[2]);
  dlclose(law.lib);
  dlclose(gear_fmu.lib);
  printf("%d passed, %d failed\n", passed, failed);
  return failed ? 1 : 0;
}
