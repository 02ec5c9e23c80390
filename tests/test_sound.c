/* test_sound.c: the sound layer's modules: the built-in sounds (pitch against size),
 * placement by the head pose, the mixer's reference loudness, timing and limiter,
 * sound files (resampling, bad files) and the engine end to end into a WAV file,
 * read back with libsndfile, and a soundtrack that cannot be written saying why. */
#include "check.h"
#include "scratch.h"

#include <dirent.h>
#include <signal.h>
#include <stdbool.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <unistd.h>

#include <sndfile.h>

#include "sound/clip.h"
#include "sound/mixer.h"
#include "sound/place.h"
#include "sound/sound.h"
#include "sound/synth.h"
#include "sound/track.h"
#include "tone.h"

static int setup(void **state)
{
    (void)state;
    return scratch_make("sound");
}

static int teardown(void **state)
{
    (void)state;
    return scratch_remove();
}

static void path_in_dir(char *out, size_t len, const char *name)
{
    snprintf(out, len, "%s/%s", g_dir, name);
}

/* The strongest frequency of x (n samples at 48 kHz) from 20 Hz to 20 kHz, to a
 * quarter of a hertz (tone.h). */
static double strongest(const float *x, long n)
{
    double *d = malloc((size_t)n * sizeof *d);
    assert_non_null(d);
    for (long k = 0; k < n; k++) d[k] = x[k];
    double f = tone_strongest(d, n, SOUND_RATE, 20, 20000, 10);
    free(d);
    return f;
}

static float peak_of(const sound_buf *b)
{
    float p = 0;
    for (long i = 0; i < b->n; i++) p = fmaxf(p, fabsf(b->x[i]));
    return p;
}

static void builtin_sounds_fall_in_pitch_as_objects_grow(void **state)
{
    (void)state;
    assert_int_equal(synth_find("click"), SYNTH_CLICK);
    assert_int_equal(synth_find("knock"), SYNTH_KNOCK);
    assert_int_equal(synth_find("bell"), SYNTH_BELL);
    assert_int_equal(synth_find("gong"), -1);
    for (int k = 0; k < SYNTH_KINDS; k++) {
        double prev = 1e9;
        for (double size = 0.05; size <= 0.4; size *= 2) {
            sound_buf *b = synth_make(k, synth_pitch(k, size));
            assert_non_null(b);
            assert_true(b->n > 0 && b->n <= 4 * SOUND_RATE);
            assert_near(peak_of(b), 1.0, 1e-6);
            /* the first 50 ms hold every mode; the lowest rings longest, so the strongest
             * frequency of the whole sound is its fundamental scaled by size */
            long n = b->n < 4800 ? b->n : 4800;
            double f = strongest(b->x, n);
            if (!(f < prev)) fail_msg("kind %d: %g Hz at %g m, not below %g Hz", k, f, size, prev);
            prev = f;
            sbuf_unref(b);
        }
    }
    /* twice the size, half the pitch (within the held range) */
    assert_near(synth_pitch(SYNTH_KNOCK, 0.2), 0.5 * synth_pitch(SYNTH_KNOCK, 0.1), 1e-12);
    /* held: the lowest mode stays within 40 Hz .. 16 kHz */
    assert_true(synth_pitch(SYNTH_CLICK, 1e-6) * 2900 <= 16000 + 1e-9);
    assert_true(synth_pitch(SYNTH_BELL, 1e6) * 440 >= 40 - 1e-9);
}

static void placement_follows_the_head(void **state)
{
    (void)state;
    sound_listener l = {v3(0, 0, 0), v3(0, 1, 0), v3(0, 0, 1)}; /* looking along +y, x right */
    place_result r = place_hit(&l, v3(0, 1, 0));                /* 1 m ahead */
    assert_near(r.dist, 1, 1e-12);
    for (int e = 0; e < 2; e++) {
        assert_near(r.delay[e], 1 / 343.0, 1e-12);
        assert_near(r.gain[e], 1, 1e-12);
    }
    r = place_hit(&l, v3(-2, 0, 0)); /* 2 m to the left */
    assert_true(r.delay[0] < r.delay[1]);
    assert_true(r.gain[0] > r.gain[1]);
    assert_near(r.gain[0], 0.5, 1e-12);
    assert_near(r.gain[1], 0.5 * 0.3, 1e-12);
    double itd = 0.0875 / 343 * (M_PI / 2 + 1); /* Woodworth at 90 degrees: 0.656 ms */
    assert_near(r.delay[1] - r.delay[0], itd, 1e-12);
    assert_near(0.5 * (r.delay[0] + r.delay[1]), 2 / 343.0, 1e-12);
    r = place_hit(&l, v3(3, 0.5, 0)); /* to the right */
    assert_true(r.delay[1] < r.delay[0]);
    assert_true(r.gain[1] > r.gain[0]);
    r = place_hit(&l, v3(0, 0, 0)); /* at the head: loud, not infinite */
    assert_near(r.gain[0], 1 / PLACE_MIN_DIST, 1e-9);
    assert_true(r.delay[0] >= 0 && r.delay[1] >= 0);
    sound_listener bad = {v3(0, 0, 0), v3(0, 0, 0), v3(0, 0, 1)}; /* no view direction */
    r = place_hit(&bad, v3(-1, 0, 0));
    assert_near(r.gain[0], r.gain[1], 0);
}

/* A buffer of n samples of value v. */
static sound_buf *flat(long n, float v)
{
    sound_buf *b = sbuf_new(n);
    assert_non_null(b);
    for (long i = 0; i < n; i++) b->x[i] = v;
    return b;
}

static void mixer_starts_each_voice_at_its_sample(void **state)
{
    (void)state;
    mixer *m = mixer_new();
    assert_non_null(m);
    sound_buf *b = flat(100, 1);
    long start[2] = {1000, 1017};
    double gain[2] = {0.25, 0.1};
    mixer_add(m, b, start, gain);
    sbuf_unref(b); /* the voice keeps its own reference */
    int16_t out[2 * 2000];
    assert_int_equal(mixer_render(m, 2000, out), 2000);
    for (long k = 0; k < 2000; k++) {
        int16_t l = k >= 1000 && k < 1100 ? 8192 : 0, r = k >= 1017 && k < 1117 ? 3277 : 0;
        if (out[2 * k] != l || out[2 * k + 1] != r)
            fail_msg("sample %ld: %d %d, want %d %d", k, out[2 * k], out[2 * k + 1], l, r);
    }
    assert_int_equal(mixer_voices(m), 0); /* ended voices are let go */
    /* a voice that would start in the past starts now, whole */
    long past[2] = {1500, 1510};
    b = flat(10, 1);
    mixer_add(m, b, past, gain);
    sbuf_unref(b);
    assert_int_equal(mixer_render(m, 2100, out), 100);
    assert_int_equal(out[0], 8192);
    assert_int_equal(out[2 * 10 + 1], 3277);
    assert_int_equal(out[2 * 20], 0);
    /* NaN, negative and inaudible gains play nothing */
    double silent[3][2] = {{NAN, NAN}, {-1, -2}, {1e-7, 1e-7}};
    b = flat(10, 1);
    long now[2] = {2100, 2100};
    for (int i = 0; i < 3; i++) mixer_add(m, b, now, silent[i]);
    sbuf_unref(b);
    assert_int_equal(mixer_voices(m), 0);
    mixer_free(m);
}

static void the_limiter_never_clips(void **state)
{
    (void)state;
    mixer *m = mixer_new();
    sound_buf *b = synth_make(SYNTH_KNOCK, 1.0);
    /* 5,000 loud collisions at once, and a quiet one long after */
    for (int i = 0; i < 5000; i++) {
        long start[2] = {4800 + i % 7, 4800 + i % 5};
        double gain[2] = {3.0 + i % 3, 2.0};
        mixer_add(m, b, start, gain);
    }
    assert_int_equal(mixer_voices(m), MIXER_VOICES);
    long n = b->n + 48000;
    int16_t *out = malloc(2 * (size_t)n * sizeof *out);
    double *sum = malloc(2 * (size_t)n * sizeof *sum);
    assert_non_null(out);
    assert_non_null(sum);
    mixer_peek(m, 0, n, sum);
    assert_int_equal(mixer_render(m, n, out), n);
    int most = 0;
    long same_sign = 0, loud = 0;
    for (long k = 0; k < 2 * n; k++) {
        most = abs(out[k]) > most ? abs(out[k]) : most;
        if (fabs(sum[k]) > 1) { /* no wrap-around: the sign of the sum is kept */
            loud++;
            same_sign += (sum[k] > 0) == (out[k] > 0);
        }
    }
    if (most >= 32767 || most > (int)(MIXER_CEILING * 32767) + 1)
        fail_msg("a sample reached %d", most);
    assert_true(most > 25000); /* limited, not silenced */
    assert_true(loud > 1000);
    assert_true(same_sign >= loud - loud / 100);
    /* below the ceiling the output is the sum itself, once the gain has recovered */
    long start[2] = {n + 48000, n + 48000};
    double g[2] = {0.25, 0.25};
    mixer_add(m, b, start, g);
    long n2 = n + 48000 + 4800;
    int16_t *out2 = malloc(2 * (size_t)(n2 - n) * sizeof *out2);
    mixer_render(m, n2, out2);
    int p = 0;
    for (long k = 0; k < 2 * (n2 - n); k++) p = abs(out2[k]) > p ? abs(out2[k]) : p;
    assert_int_equal(p, 8192);
    free(out);
    free(out2);
    free(sum);
    sbuf_unref(b);
    mixer_free(m);
}

/* Writes a mono tone of f Hz, n samples at rate, with libsndfile in format fmt. */
static void write_tone(const char *path, int rate, int fmt, double f, long n)
{
    SF_INFO info = {.samplerate = rate, .channels = 1, .format = fmt};
    SNDFILE *s = sf_open(path, SFM_WRITE, &info);
    assert_non_null(s);
    float *x = malloc((size_t)n * sizeof *x);
    for (long i = 0; i < n; i++) x[i] = (float)(0.3 * sin(2 * M_PI * f * (double)i / rate));
    assert_int_equal(sf_writef_float(s, x, n), n);
    sf_close(s);
    free(x);
}

static void sound_files_are_resampled_and_checked(void **state)
{
    (void)state;
    char path[256], err[512];
    path_in_dir(path, sizeof path, "tone.flac");
    write_tone(path, 44100, SF_FORMAT_FLAC | SF_FORMAT_PCM_16, 660, 44100 / 2);
    sound_buf *b = clip_load(path, err, sizeof err);
    if (!b) fail_msg("%s", err);
    assert_near((double)b->n, 24000, 2);       /* half a second at 48 kHz */
    assert_near(peak_of(b), 1, 1e-6);          /* normalised */
    assert_near(strongest(b->x + 2000, 19000), 660, 1);
    sbuf_unref(b);

    path_in_dir(path, sizeof path, "missing.wav");
    assert_null(clip_load(path, err, sizeof err));
    assert_non_null(strstr(err, "cannot read"));
    assert_null(clip_load(g_dir, err, sizeof err));
    assert_non_null(strstr(err, "is a folder"));
    path_in_dir(path, sizeof path, "empty.wav");
    fclose(fopen(path, "w"));
    assert_null(clip_load(path, err, sizeof err));
    assert_non_null(strstr(err, "is empty"));
    path_in_dir(path, sizeof path, "text.wav");
    FILE *f = fopen(path, "w");
    fputs("this is not a sound, only words about one\n", f);
    fclose(f);
    assert_null(clip_load(path, err, sizeof err));
    assert_non_null(strstr(err, "not a sound file"));
    path_in_dir(path, sizeof path, "silence.wav"); /* a header and no frames */
    write_tone(path, 48000, SF_FORMAT_WAV | SF_FORMAT_PCM_16, 1, 0);
    assert_null(clip_load(path, err, sizeof err));
    assert_non_null(strstr(err, "no sound"));
}

/* True when a part file (outfile.h) is left in the scratch folder. */
static bool part_files_left(void)
{
    DIR *d = opendir(g_dir);
    assert_non_null(d);
    bool left = false;
    for (struct dirent *e; (e = readdir(d)) != NULL;)
        if (strstr(e->d_name, "vroc-part")) left = true;
    closedir(d);
    return left;
}

/* Reads a 48 kHz stereo 16-bit WAV file whole: *n samples. */
static short *read_wav(const char *path, long *n)
{
    SF_INFO info;
    memset(&info, 0, sizeof info);
    SNDFILE *s = sf_open(path, SFM_READ, &info);
    assert_non_null(s);
    assert_int_equal(info.samplerate, 48000);
    assert_int_equal(info.channels, 2);
    assert_int_equal(info.format, SF_FORMAT_WAV | SF_FORMAT_PCM_16);
    short *x = calloc(2 * (size_t)info.frames + 2, sizeof *x);
    assert_int_equal(sf_readf_short(s, x, info.frames), info.frames);
    sf_close(s);
    *n = (long)info.frames;
    return x;
}

static void the_engine_writes_the_reference_loudness_on_time(void **state)
{
    (void)state;
    char path[256], err[512];
    path_in_dir(path, sizeof path, "track.wav");
    sound_engine *e = sound_new();
    assert_non_null(e);
    assert_false(sound_active(e));
    assert_int_equal(sound_track_open(e, path, 0, err, sizeof err), 0);
    sound_settings set = sound_settings_defaults();
    sound_listener l = {v3(0, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
    /* 1 N s, 1 m ahead, all volumes 1, at 0.125 s into the second frame */
    sound_hit h = {.t = 0.225, .p = v3(0, 1, 0), .j = 1, .gain = 1, .size = 0.1};
    assert_int_equal(sound_frame(e, &set, &l, NULL, 0, 0, 0.1, -1, err, sizeof err), 0);
    assert_int_equal(sound_frame(e, &set, &l, &h, 1, 0.1, 0.3, -1, err, sizeof err), 0);
    assert_int_equal(sound_frame(e, &set, &l, NULL, 0, 0.3, 0.5, -1, err, sizeof err), 0);
    assert_int_equal(sound_track_close(e, 0.5, err, sizeof err), 0);
    long n;
    short *x = read_wav(path, &n);
    assert_int_equal(n, 24000); /* 0.5 s */
    long first = -1;
    int peak = 0;
    for (long k = 0; k < n; k++) {
        if (first < 0 && (x[2 * k] != 0 || x[2 * k + 1] != 0)) first = k;
        peak = abs(x[2 * k]) > peak ? abs(x[2 * k]) : peak;
        assert_int_equal(x[2 * k], x[2 * k + 1]); /* straight ahead: both ears alike */
    }
    /* the click's first sample is 0 (a sine), so sound shows from the next one */
    assert_int_equal(first, lround((0.225 + 1 / 343.0) * 48000) + 1);
    assert_int_equal(peak, 8192); /* a quarter of full scale */
    free(x);

    /* collision_vol and the objects' volumes multiply; off and 0 are silent */
    path_in_dir(path, sizeof path, "quiet.wav");
    assert_int_equal(sound_track_open(e, path, 0.5, err, sizeof err), 0);
    h.t = 0.6;
    h.gain = 0.5;
    sound_frame(e, &set, &l, &h, 1, 0.5, 0.7, -1, err, sizeof err);
    snprintf(set.collision_sound, sizeof set.collision_sound, "off");
    h.t = 0.8;
    sound_frame(e, &set, &l, &h, 1, 0.7, 0.9, -1, err, sizeof err);
    assert_int_equal(sound_track_close(e, 0.9, err, sizeof err), 0);
    x = read_wav(path, &n);
    assert_int_equal(n, 19200);
    peak = 0;
    for (long k = 0; k < n; k++) {
        peak = abs(x[2 * k]) > peak ? abs(x[2 * k]) : peak;
        if (k >= 14400) assert_int_equal(x[2 * k], 0); /* the off collision */
    }
    assert_int_equal(peak, 4096);
    free(x);
    assert_false(sound_active(e));
    assert_int_equal(sound_free(e, 0.9, err, sizeof err), 0);
}

static void a_soundtrack_that_cannot_be_written_is_an_error(void **state)
{
    (void)state;
    char err[512];
    sound_engine *e = sound_new();
    assert_int_equal(sound_track_open(e, "/nonexistent/dir/t.wav", 0, err, sizeof err), -1);
    assert_non_null(strstr(err, "cannot write '/nonexistent/dir/t.wav'"));
    assert_int_equal(sound_track_open(e, g_dir, 0, err, sizeof err), -1);
    assert_null(sound_track_path(e));
    /* the system's reason, though libsndfile writes the file (shell/outfile.h) */
    assert_int_equal(sound_track_open(e, "/dev/full", 0, err, sizeof err), -1);
    assert_string_equal(err, "cannot write '/dev/full': No space left on device");
    assert_null(sound_track_path(e));
    assert_int_equal(sound_choose(e, "/nonexistent.wav", err, sizeof err), -1);
    assert_int_equal(sound_choose(e, "bell", err, sizeof err), 0);
    assert_int_equal(sound_choose(e, "off", err, sizeof err), 0);
    assert_int_equal(sound_free(e, 0, err, sizeof err), 0);
}

/* A soundtrack that outgrows the file size limit fails in the frame that
 * crosses it, with the system's reason, and is closed there: its header tells
 * the samples that were written. */
static void a_soundtrack_that_outgrows_the_size_limit_says_why(void **state)
{
    (void)state;
    char path[256], err[512];
    path_in_dir(path, sizeof path, "limited.wav");
    sound_engine *e = sound_new();
    assert_int_equal(sound_track_open(e, path, 0, err, sizeof err), 0);
    sound_settings set = sound_settings_defaults();
    sound_listener l = {v3(0, 0, 0), v3(0, 1, 0), v3(0, 0, 1)};
    struct rlimit old, lim;
    getrlimit(RLIMIT_FSIZE, &old);
    lim = old;
    lim.rlim_cur = 10000; /* 0.05 s of sound and a header */
    void (*was)(int) = signal(SIGXFSZ, SIG_IGN);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    int first = sound_frame(e, &set, &l, NULL, 0, 0, 0.02, -1, err, sizeof err);
    int second = sound_frame(e, &set, &l, NULL, 0, 0.02, 0.1, -1, err, sizeof err);
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, was);
    assert_int_equal(first, 0);
    assert_int_equal(second, 1);
    char want[300];
    snprintf(want, sizeof want, "cannot write '%s': File too large", path);
    assert_string_equal(err, want);
    assert_null(sound_track_path(e));
    /* given up: no file at its path, and no part file beside it */
    assert_int_equal(access(path, F_OK), -1);
    assert_false(part_files_left());
    assert_int_equal(sound_free(e, 0.1, err, sizeof err), 0);

    /* a soundtrack that fails over an old file leaves it whole */
    FILE *f = fopen(path, "w");
    fputs("the old file\n", f);
    fclose(f);
    e = sound_new();
    assert_int_equal(sound_track_open(e, path, 0, err, sizeof err), 0);
    was = signal(SIGXFSZ, SIG_IGN);
    assert_int_equal(setrlimit(RLIMIT_FSIZE, &lim), 0);
    second = sound_frame(e, &set, &l, NULL, 0, 0, 0.1, -1, err, sizeof err);
    setrlimit(RLIMIT_FSIZE, &old);
    signal(SIGXFSZ, was);
    assert_int_equal(second, 1);
    char back[64] = "";
    f = fopen(path, "r");
    assert_non_null(fgets(back, sizeof back, f));
    fclose(f);
    assert_string_equal(back, "the old file\n");
    assert_false(part_files_left());
    assert_int_equal(sound_free(e, 0.1, err, sizeof err), 0);
}

/* The header of a soundtrack of frames frames, with the RIFF limit riff_max. */
static void header_of(unsigned char h[TRACK_HEADER_BYTES], uint64_t frames, uint64_t riff_max)
{
    memset(h, 0xaa, TRACK_HEADER_BYTES);
    track_header(h, frames, riff_max);
}

static uint64_t le(const unsigned char *p, int bytes)
{
    uint64_t v = 0;
    for (int k = bytes - 1; k >= 0; k--) v = v << 8 | p[k];
    return v;
}

/* Beyond 4 GiB a soundtrack is RF64 (EBU Tech 3306): the sizes in ds64, 0xffffffff
 * in the 32-bit fields; just inside, RIFF with the same layout (a JUNK chunk in
 * ds64's place).  Checked on the header writer, and on a small file whose limit
 * is lowered, which libsndfile (the reader the tests trust) reads back. */
static void a_soundtrack_beyond_4_gib_is_rf64(void **state)
{
    (void)state;
    unsigned char h[TRACK_HEADER_BYTES];
    /* the RIFF size is the file's length less 8: 72 + 4 frames */
    uint64_t inside = (TRACK_RIFF_MAX - 72) / 4, outside = inside + 1;
    header_of(h, inside, TRACK_RIFF_MAX);
    assert_memory_equal(h, "RIFF", 4);
    assert_int_equal(le(h + 4, 4), 72 + 4 * inside);
    assert_memory_equal(h + 8, "WAVEJUNK", 8);
    assert_int_equal(le(h + 16, 4), 28);
    assert_memory_equal(h + 48, "fmt ", 4);
    assert_int_equal(le(h + 60, 4), 48000);
    assert_int_equal(le(h + 64, 4), 192000);
    assert_int_equal(le(h + 68, 2), 4);
    assert_int_equal(le(h + 70, 2), 16);
    assert_memory_equal(h + 72, "data", 4);
    assert_int_equal(le(h + 76, 4), 4 * inside);
    header_of(h, outside, TRACK_RIFF_MAX);
    assert_memory_equal(h, "RF64", 4);
    assert_int_equal(le(h + 4, 4), 0xffffffffu);
    assert_memory_equal(h + 8, "WAVEds64", 8);
    assert_int_equal(le(h + 20, 8), 72 + 4 * outside);
    assert_int_equal(le(h + 28, 8), 4 * outside);
    assert_int_equal(le(h + 36, 8), outside);
    assert_int_equal(le(h + 76, 4), 0xffffffffu);
    /* six hours and forty minutes, which a 32-bit size wrapped to 27 minutes */
    uint64_t long_run = 48000ULL * (6 * 3600 + 40 * 60);
    header_of(h, long_run, TRACK_RIFF_MAX);
    assert_int_equal(le(h + 36, 8), long_run);
    assert_int_equal(le(h + 28, 8), 4 * long_run);

    /* a file of 1000 frames, RF64 for a limit of 1000 bytes: libsndfile reads it */
    char path[256];
    path_in_dir(path, sizeof path, "small-rf64.wav");
    FILE *f = fopen(path, "wb");
    header_of(h, 1000, 1000);
    assert_memory_equal(h, "RF64", 4);
    fwrite(h, 1, sizeof h, f);
    for (int i = 0; i < 1000; i++) {
        unsigned char s[4] = {(unsigned char)i, (unsigned char)(i >> 8), 0, 0};
        fwrite(s, 1, 4, f);
    }
    fclose(f);
    SF_INFO info;
    memset(&info, 0, sizeof info);
    SNDFILE *in = sf_open(path, SFM_READ, &info);
    if (!in) fail_msg("libsndfile: %s", sf_strerror(NULL));
    assert_int_equal(info.format & SF_FORMAT_TYPEMASK, SF_FORMAT_RF64);
    assert_int_equal(info.frames, 1000);
    assert_int_equal(info.channels, 2);
    assert_int_equal(info.samplerate, 48000);
    short x[2000];
    assert_int_equal(sf_readf_short(in, x, 1000), 1000);
    assert_int_equal(x[2 * 999], 999);
    sf_close(in);
}

int main(void)
{
    const struct CMUnitTest tests[] = {
        cmocka_unit_test(builtin_sounds_fall_in_pitch_as_objects_grow),
        cmocka_unit_test(placement_follows_the_head),
        cmocka_unit_test(mixer_starts_each_voice_at_its_sample),
        cmocka_unit_test(the_limiter_never_clips),
        cmocka_unit_test_setup_teardown(sound_files_are_resampled_and_checked, setup, teardown),
        cmocka_unit_test_setup_teardown(the_engine_writes_the_reference_loudness_on_time, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(a_soundtrack_that_cannot_be_written_is_an_error, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(a_soundtrack_that_outgrows_the_size_limit_says_why, setup,
                                        teardown),
        cmocka_unit_test_setup_teardown(a_soundtrack_beyond_4_gib_is_rf64, setup, teardown),
    };
    return cmocka_run_group_tests(tests, NULL, NULL);
}
