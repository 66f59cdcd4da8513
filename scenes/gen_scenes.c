/* gen_scenes.c - writes torusrt's NFF scene files: the paper's two images and the stiff cases.
 *
 * Usage:
 *   torusrt-genscenes OUTDIR            write every scene as OUTDIR/NAME.nff (and a moving
 *                                       scene's motion file as OUTDIR/NAME.motion)
 *   torusrt-genscenes OUTDIR NAME...    write only the named scenes
 *   torusrt-genscenes --variant BASE KEY=VALUE,... OUTDIR NAME
 *                                       write a variant of paper-image1 or paper-image2 as
 *                                       OUTDIR/NAME.nff (docs/fidelity-protocol.md)
 *   torusrt-genscenes --list            print every name with a one-line description
 *   torusrt-genscenes --help            print this usage
 * Returns 0 on success, 1 when a file cannot be written, 2 on a usage error (unknown name,
 * missing OUTDIR, an OUTDIR that is no folder). Each file is written to a new temporary .NAME.nff.XXXXXX beside it
 * (mkstemp: never a file of the user's, never through a link) and renamed, so a failed run never leaves a partial
 * NAME.nff behind; a NAME.nff that is a link has its target written.
 *
 * Output is byte-reproducible: no clock, no rand(); the one pseudo-random placement uses a
 * fixed-seed 64-bit LCG. Every coordinate computed with libm is rounded to 9 significant
 * digits when the scene is built, and every number is printed as the shortest decimal that
 * reads back as the same double (up to "%.17g"), so the scaled scenes hold the exact products
 * of the base numbers and their factor.
 *
 * C11, libc and libm, and the stopping signals' handler of the other executables
 * (support/signal_cleanup_c.h: a stopping signal removes the temporary being written, says
 * "torusrt-genscenes: stopped by SIGNAME" and ends with 128 + N). This file holds the table of
 * scenes, the command line and the file writing; the rest is in gen/:
 *   gen/scene.{h,c}         the scene in memory and the calls the builders use, framing
 *   gen/nff_writer.{h,c}    rounding (q9), the LCG, round-trip numbers, writing NFF text
 *   gen/builders.h          one builder per scene, declared for the table below
 *   gen/paper_scenes.c      paper-image1 and paper-image2 (and orbiting-mirror, image 2 moving)
 *   gen/motion_scenes.c     bouncing-balls and the moving scenes' motion files
 *   gen/stiff_scenes.c      the stiff and extreme cases
 */
#define _DEFAULT_SOURCE /* realpath, lstat, mkstemp, fchmod */
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>

#include "gen/builders.h"
#include "rt_number.h"
#include "gen/nff_writer.h"
#include "gen/scene.h"
#include "signal_cleanup_c.h"

/* ---------------------------------------------------------------- table and main */

typedef struct {
    const char *name;
    const char *desc;
    void (*build)(scene *sc);
    double factor; /* scale applied when writing */
} scene_def;

static const scene_def SCENES[] = {
    {"paper-image1", "the paper's image 1: 369 recursively defined diffuse spheres (columns at z = -5, 0, +5), 144x144",
     build_paper_image1, 1},
    {"paper-image2",
     "the paper's image 2: glass and mirror sphere before 121 small spheres, "
     "144x144",
     build_paper_image2, 1},
    {"paper-image1-planar", "image 1's nine flakes in one plane, z = 0", build_paper_image1_planar, 1},
    {"paper-image1-planar-z", "image 1's nine flakes in three columns at z = -5, 0, +5 (round one's image 1)",
     build_paper_image1_planar_z, 1},
    {"paper-image2-floor", "image 2 with the 121 small spheres on the floor (round one's image 2)",
     build_paper_image2_floor, 1},
    {"paper-image1-cube", "image 1's nine flakes at the centre and corners of a cube", build_paper_image1_cube, 1},
    {"paper-image1-tree", "image 1 as one four-level tree of 1 + 8 + 72 + 288 spheres", build_paper_image1_tree, 1},
    {"paper-image2-wall", "image 2 with the 121 small spheres on a wall behind the big ones", build_paper_image2_wall,
     1},
    {"axis-rays", "rays with zero direction components, along cell edges, parallel to faces", build_axis_rays, 1},
    {"grid-corners", "objects on the cell lattice; rays through cell edges and corners", build_grid_corners, 1},
    {"eye-inside", "the eye inside the object space, objects all around it", build_eye_inside, 1},
    {"light-inside", "a point light inside the object space, in a ring of spheres", build_light_inside, 1},
    {"grazing", "edge-on polygons, tangent rays on spheres, a floor at a very low angle", build_grazing, 1},
    {"tir", "total internal reflection inside a glass slab", build_tir, 1},
    {"facing-mirrors", "two parallel mirrors: rays bounce to the depth limit", build_facing_mirrors, 1},
    {"empty", "no objects: background only", build_empty, 1},
    {"one-big-sphere", "one sphere spanning the whole object space (nearly every cell)", build_one_big_sphere, 1},
    {"one-cell", "50 of 51 objects in one cell of the 24^3 grid", build_one_cell, 1},
    {"scale-1", "the scale test scene at scale 1", build_scaled, 1},
    {"scale-tiny", "the scale test scene times 1e-6", build_scaled, 1e-6},
    {"scale-huge", "the scale test scene times 1e6", build_scaled, 1e6},
    {"scale-pow2-tiny", "the scale test scene times 2^-20 (exact products)", build_scaled, 1.0 / 1048576.0},
    {"scale-pow2-huge", "the scale test scene times 2^20 (exact products)", build_scaled, 1048576.0},
    {"tiny-sphere", "a 1e-6 sphere close up, with a huge sphere making the space 1e6 larger", build_tiny_sphere, 1},
    {"tiny-sphere-alone", "tiny-sphere without the huge sphere (the images must be equal)", build_tiny_alone, 1},
    {"cones-and-patches", "every primitive: cone, cylinder, pp patches, concave polygon", build_cones_and_patches, 1},
    {"one-pixel", "a small scene rendered at 1x1", build_one_pixel, 1},
    {"opposing-normals", "pp triangles whose vertex normals cancel (a teapot pole)", build_opposing_normals, 1},
    {"bouncing-balls", "8 balls bouncing on a floor before a mirror, with a 64-frame motion file", build_bouncing_balls,
     1},
    {"orbiting-mirror", "image 2 whose mirror sphere circles the glass one, with a 64-frame motion file",
     build_orbiting_mirror, 1},
};

/* The moving scenes: NAME.motion is written beside NAME.nff. */
static const struct {
    const char *name;
    void (*write)(FILE *f);
} MOTIONS[] = {
    {"bouncing-balls", write_bouncing_balls_motion},
    {"orbiting-mirror", write_orbiting_mirror_motion},
};
#define NSCENES ((int)(sizeof SCENES / sizeof SCENES[0]))

static int find_scene(const char *name)
{
    for (int i = 0; i < NSCENES; ++i)
        if (strcmp(SCENES[i].name, name) == 0) return i;
    return -1;
}

/* TEXT's first N bytes as messages show them (docs/cli.md): control bytes and DEL escaped
 * (\x0a), at most 200 characters; four buffers in turn, so one message can show four texts. */
static const char *shown_n(const char *text, size_t n)
{
    static char buffers[4][200 * 4 + 4];
    static int next;
    char *out = buffers[next++ % 4], *o = out;
    size_t i = 0;
    for (; i < n && o - out < 200 * 4 - 4; ++i) {
        unsigned char c = (unsigned char)text[i];
        if (c < 0x20 || c == 0x7f) o += sprintf(o, "\\x%02x", c);
        else *o++ = (char)c;
    }
    if (i < n) o += sprintf(o, "...");
    *o = 0;
    return out;
}

static const char *shown(const char *text) { return shown_n(text, strlen(text)); }

/* The mode a new file gets from fopen: mkstemp makes 0600. */
static mode_t new_file_mode(void)
{
    mode_t mask = umask(0);
    umask(mask);
    return 0666 & ~mask;
}

/* Writes OUTDIR/NAME.EXT through a new temporary .NAME.EXT.XXXXXX in the same folder with
 * write(f, ctx); returns 0, or 1 after printing why not. A NAME.EXT that is a link is followed:
 * its target is written (the link stays), and the temporary goes beside the target. mkstemp makes
 * the temporary under a name no file has, so no file of the user's is ever removed or written. */
static int write_file(const char *outdir, const char *name, const char *ext, void (*write)(FILE *f, const void *ctx),
                      const void *ctx)
{
    size_t len = strlen(outdir) + strlen(name) + strlen(ext) + PATH_MAX + 16;
    char *path = malloc(len), *tmp = malloc(len);
    int rc = 1;
    if (!path || !tmp) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        goto done;
    }
    snprintf(path, len, "%s/%s.%s", outdir, name, ext);
    struct stat st;
    if (lstat(path, &st) == 0 && S_ISLNK(st.st_mode)) {
        char real[PATH_MAX];
        if (!realpath(path, real)) {
            fprintf(stderr, "torusrt-genscenes: %s is a link to nothing: ", shown(path));
            perror(NULL);
            goto done;
        }
        snprintf(path, len, "%s", real);
    }
    if (stat(path, &st) == 0 && !S_ISREG(st.st_mode)) {
        fprintf(stderr, "torusrt-genscenes: %s is not a regular file\n", shown(path));
        goto done;
    }
    const char *slash = strrchr(path, '/');
    size_t dir_len = slash ? (size_t)(slash - path) + 1 : 0;
    /* The base cut so that ".BASE.XXXXXX" fits NAME_MAX. */
    size_t base_len = strlen(path + dir_len), room = NAME_MAX - 8;
    if (base_len > room) base_len = room;
    snprintf(tmp, len, "%.*s.%.*s.XXXXXX", (int)dir_len, path, (int)base_len, path + dir_len);
    size_t slot = 0;
    int fd = torusrt_mkstemp_removed_on_signal(tmp, &slot);
    if (fd < 0) {
        fprintf(stderr, "torusrt-genscenes: cannot write %s: ", shown(path));
        perror(NULL);
        goto done;
    }
    FILE *f = fchmod(fd, new_file_mode()) == 0 ? fdopen(fd, "wb") : NULL;
    if (!f) {
        fprintf(stderr, "torusrt-genscenes: cannot write %s: ", shown(tmp));
        perror(NULL);
        close(fd);
        remove(tmp);
        torusrt_forget_on_signal(slot);
        goto done;
    }
    write(f, ctx);
    int bad = ferror(f);
    if (fclose(f) != 0 || bad) {
        fprintf(stderr, "torusrt-genscenes: error writing %s\n", shown(tmp));
        remove(tmp);
        torusrt_forget_on_signal(slot);
        goto done;
    }
    if (rename(tmp, path) != 0) {
        fprintf(stderr, "torusrt-genscenes: cannot rename %s to %s: ", shown(tmp), shown(path));
        perror(NULL);
        remove(tmp);
        torusrt_forget_on_signal(slot);
        goto done;
    }
    torusrt_forget_on_signal(slot); /* after the rename: a signal before it removes the temporary */
    rc = 0;
done:
    free(path);
    free(tmp);
    return rc;
}

typedef struct {
    const scene_def *def;
    const scene *sc;
} nff_job;

static void write_nff(FILE *f, const void *ctx)
{
    const nff_job *job = ctx;
    writer wr = {f, job->def->factor};
    write_scene(&wr, job->def->name, job->def->desc, job->sc);
}

static void write_motion(FILE *f, const void *ctx)
{
    for (size_t i = 0; i < sizeof MOTIONS / sizeof MOTIONS[0]; ++i)
        if (strcmp(MOTIONS[i].name, ((const scene_def *)ctx)->name) == 0) MOTIONS[i].write(f);
}

static int has_motion(const scene_def *def)
{
    for (size_t i = 0; i < sizeof MOTIONS / sizeof MOTIONS[0]; ++i)
        if (strcmp(MOTIONS[i].name, def->name) == 0) return 1;
    return 0;
}

/* Writes OUTDIR/NAME.nff (and NAME.motion for a moving scene); returns 0, or 1 after printing
 * why not. */
static int write_one(const char *outdir, const scene_def *def)
{
    scene *sc = calloc(1, sizeof *sc);
    if (!sc) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        return 1;
    }
    sc->up = v3(0, 1, 0);
    sc->factor = def->factor;
    def->build(sc);
    int rc = 1;
    if (sc->failed) {
        fprintf(stderr, "torusrt-genscenes: %s: could not build the scene (out of memory)\n", def->name);
    } else {
        nff_job job = {def, sc};
        rc = write_file(outdir, def->name, "nff", write_nff, &job);
        if (rc == 0 && has_motion(def)) rc = write_file(outdir, def->name, "motion", write_motion, def);
    }
    scene_free(sc);
    free(sc);
    return rc;
}

/* Whether NAME can name a scene file: not empty, at most 200 bytes, no '/', no control
 * character, not starting with '-' or '.' (an option, or a hidden file). */
static int good_name(const char *name)
{
    size_t n = strlen(name);
    if (n == 0 || n > 200 || name[0] == '-' || name[0] == '.') return 0;
    for (size_t i = 0; i < n; ++i)
        if (name[i] == '/' || (unsigned char)name[i] < 0x20 || name[i] == 0x7f) return 0;
    return 1;
}

/* One KEY=VALUE of a variant into *v; 0, or 2 after printing why not. */
static int variant_setting(const char *setting, paper_variant *v)
{
    static const struct {
        const char *name;
        int image, layout;
    } layouts[] = {{"planar-z", 1, PAPER_PLANAR_Z}, {"planar", 1, PAPER_PLANAR}, {"cube", 1, PAPER_CUBE},
                   {"tree", 1, PAPER_TREE},         {"floor", 2, PAPER_FLOOR},   {"wall", 2, PAPER_WALL}};
    const char *eq = strchr(setting, '=');
    if (!eq) {
        fprintf(stderr, "torusrt-genscenes: --variant setting '%s' is not KEY=VALUE\n", shown(setting));
        return 2;
    }
    size_t klen = (size_t)(eq - setting);
    const char *value = eq + 1;
    const char *key = v->image == 1 ? "layout" : "plane";
    if (klen == strlen(key) && strncmp(setting, key, klen) == 0) {
        for (size_t i = 0; i < sizeof layouts / sizeof layouts[0]; ++i)
            if (layouts[i].image == v->image && strcmp(layouts[i].name, value) == 0) {
                v->layout = layouts[i].layout;
                return 0;
            }
        fprintf(stderr, "torusrt-genscenes: --variant %s '%s': expected %s\n", key, shown(value),
                v->image == 1 ? "planar-z, planar, cube or tree" : "floor or wall");
        return 2;
    }
    /* The numbers: a plain decimal within the key's range. */
    struct {
        const char *name;
        double lo, hi;
        int image; /* 0: both */
        int whole;
    } numbers[] = {
        {"scale", 0.25, 4, 1, 0}, {"radius", 0.5, 4, 2, 0}, {"lights", 1, 3, 0, 1}, {"margin", 0.5, 2, 0, 0}};
    for (size_t i = 0; i < sizeof numbers / sizeof numbers[0]; ++i) {
        if (klen != strlen(numbers[i].name) || strncmp(setting, numbers[i].name, klen) != 0) continue;
        if (numbers[i].image && numbers[i].image != v->image) break;
        /* The one strict syntax (rt_number.h), with its reason, then the key's range. */
        double x = 0;
        rt_number_fault fault = rt_number_real(value, strlen(value), &x);
        if (fault != RT_NUMBER_OK) {
            fprintf(stderr, "torusrt-genscenes: --variant %s '%s' %s\n", numbers[i].name, shown(value),
                    rt_number_fault_text(fault));
            return 2;
        }
        if (!(x >= numbers[i].lo && x <= numbers[i].hi) || (numbers[i].whole && strpbrk(value, ".eE"))) {
            fprintf(stderr, "torusrt-genscenes: --variant %s '%s': expected a%s number from %g to %g\n",
                    numbers[i].name, shown(value), numbers[i].whole ? " whole" : "", numbers[i].lo, numbers[i].hi);
            return 2;
        }
        switch (i) {
        case 0: v->scale = x; break;
        case 1: v->big_radius = x; break;
        case 2: v->lights = (int)x; break;
        default: v->margin = x; break;
        }
        return 0;
    }
    fprintf(stderr, "torusrt-genscenes: --variant of paper-image%d takes %s\n", v->image,
            v->image == 1 ? "layout, scale, lights and margin" : "plane, radius, lights and margin");
    return 2;
}

/* --variant BASE SETTINGS OUTDIR NAME: returns the exit status. */
static int write_variant(const char *base, const char *settings, const char *outdir, const char *name)
{
    int image = strcmp(base, "paper-image1") == 0 ? 1 : strcmp(base, "paper-image2") == 0 ? 2 : 0;
    if (!image) {
        fprintf(stderr, "torusrt-genscenes: --variant '%s': expected paper-image1 or paper-image2\n", shown(base));
        return 2;
    }
    if (!good_name(name)) {
        fprintf(stderr,
                "torusrt-genscenes: --variant NAME '%s': expected a file name without '/' or control "
                "characters, not starting with '-' or '.'\n",
                shown(name));
        return 2;
    }
    paper_variant v = paper_variant_default(image);
    char *copy = malloc(strlen(settings) + 1);
    if (!copy) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        return 1;
    }
    strcpy(copy, settings);
    int rc = 0;
    char seen[32][16];
    size_t n_seen = 0;
    /* Every item KEY=VALUE, none empty, no key twice. */
    for (char *s = copy, *next; s && rc == 0; s = next) {
        next = strchr(s, ',');
        if (next) *next++ = 0;
        const char *eq = strchr(s, '=');
        size_t klen = eq ? (size_t)(eq - s) : strlen(s);
        if (!*s || klen >= sizeof seen[0]) {
            fprintf(stderr, "torusrt-genscenes: --variant '%s': an empty or overlong setting\n", shown(settings));
            rc = 2;
            break;
        }
        for (size_t k = 0; k < n_seen && rc == 0; ++k)
            if (strncmp(seen[k], s, klen) == 0 && seen[k][klen] == 0) {
                fprintf(stderr, "torusrt-genscenes: --variant: '%s' given twice\n", shown_n(s, klen));
                rc = 2;
            }
        if (rc) break;
        if (n_seen < 32) {
            memcpy(seen[n_seen], s, klen);
            seen[n_seen++][klen] = 0;
        }
        rc = variant_setting(s, &v);
    }
    free(copy);
    if (rc) return rc;
    scene *sc = calloc(1, sizeof *sc);
    if (!sc) {
        fprintf(stderr, "torusrt-genscenes: out of memory\n");
        return 1;
    }
    sc->up = v3(0, 1, 0);
    sc->factor = 1;
    static const char *layout_names[] = {"planar-z", "planar", "cube", "tree", "floor", "wall"};
    if (image == 1) {
        note(sc, "A variant of the paper's image 1 (docs/fidelity-protocol.md, scene work): layout %s,",
             layout_names[v.layout]);
        note(sc, "every sphere's radius x %g with the centres kept, %d light(s) of the same total", v.scale, v.lights);
        note(sc, "intensity, the view angle framing every sphere with margin %g.", v.margin);
        build_image1_layout(sc, &v);
    } else {
        note(sc, "A variant of the paper's image 2 (docs/fidelity-protocol.md, scene work): plane %s,",
             layout_names[v.layout]);
        note(sc, "glass and mirror spheres of radius %g, %d light(s) of the same total intensity,", v.big_radius,
             v.lights);
        note(sc, "the view angle framing every sphere with margin %g.", v.margin);
        build_image2_plane(sc, &v);
    }
    rc = 1;
    if (sc->failed) {
        fprintf(stderr, "torusrt-genscenes: %s: could not build the scene (out of memory)\n", name);
    } else {
        scene_def def = {name, image == 1 ? "a variant of the paper's image 1" : "a variant of the paper's image 2",
                         NULL, 1};
        nff_job job = {&def, sc};
        rc = write_file(outdir, name, "nff", write_nff, &job);
    }
    scene_free(sc);
    free(sc);
    if (rc == 0) printf("torusrt-genscenes: wrote %s/%s.nff\n", outdir, name);
    return rc;
}

static void usage(FILE *f)
{
    fputs("usage: torusrt-genscenes OUTDIR [NAME...]\n"
          "       torusrt-genscenes --variant paper-image1|paper-image2 KEY=VALUE,... OUTDIR NAME\n"
          "       torusrt-genscenes --list | --help\n"
          "Writes torusrt's scenes as OUTDIR/NAME.nff (all of them, or only the NAMEs given),\n"
          "and a moving scene's motion file as OUTDIR/NAME.motion.\n"
          "OUTDIR must exist. Output is deterministic and byte-reproducible.\n"
          "  --variant  write a variant of a paper image as OUTDIR/NAME.nff: image 1 takes\n"
          "           layout=planar-z|planar|cube|tree, scale=F (sphere radii, 0.25-4),\n"
          "           lights=1|2|3, margin=F (framing, 0.5-2); image 2 takes plane=floor|wall,\n"
          "           radius=F (glass and mirror spheres, 0.5-4), lights, margin\n"
          "  --list   print every scene name with a one-line description\n"
          "  --help   print this message\n",
          f);
}

/* 0 when standard output took everything written to it, else 1 after saying so. */
static int stdout_written(void)
{
    if (fflush(stdout) == 0 && !ferror(stdout)) return 0;
    fprintf(stderr, "torusrt-genscenes: standard output: cannot write: %s\n", strerror(errno));
    return 1;
}

/* Whether standard output or error is redirected to a regular file a word of the command line
 * names (`torusrt-genscenes s.nff 2>> s.nff`): the program then ends (exit 2) before any
 * message could be appended to it, its own message about standard error going to the terminal
 * (or nowhere). */
static int stream_named(int argc, char **argv)
{
    for (int fd = 2; fd >= 1; --fd) {
        struct stat so, st;
        if (fstat(fd, &so) != 0 || !S_ISREG(so.st_mode)) continue;
        for (int a = 1; a < argc; ++a) {
            if (stat(argv[a], &st) != 0 || st.st_dev != so.st_dev || st.st_ino != so.st_ino) continue;
            if (fd == 2) {
                int tty = open("/dev/tty", O_WRONLY | O_NOCTTY);
                if (tty < 0) tty = open("/dev/null", O_WRONLY);
                if (tty >= 0 && tty != 2) {
                    dup2(tty, 2);
                    close(tty);
                }
            }
            fprintf(stderr, "torusrt-genscenes: standard %s is redirected to '%s', a file the command line names\n",
                    fd == 1 ? "output" : "error", shown(argv[a]));
            return 1;
        }
    }
    return 0;
}

int main(int argc, char **argv)
{
    torusrt_stop_on_signals("torusrt-genscenes"); /* a stopping signal: message, 128 + N, no temporary */
    if (stream_named(argc, argv)) return 2;
    if (argc < 2) {
        usage(stderr);
        return 2;
    }
    if ((strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "--list") == 0) && argc > 2) {
        fprintf(stderr, "torusrt-genscenes: %s takes nothing after it (given '%s')\n", argv[1], shown(argv[2]));
        return 2;
    }
    if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0) {
        usage(stdout);
        return stdout_written();
    }
    if (strcmp(argv[1], "--list") == 0) {
        for (int i = 0; i < NSCENES; ++i) printf("%-18s %s\n", SCENES[i].name, SCENES[i].desc);
        return stdout_written();
    }
    if (strcmp(argv[1], "--variant") == 0) {
        if (argc != 6) {
            usage(stderr);
            return 2;
        }
        if (!*argv[4]) {
            fprintf(stderr, "torusrt-genscenes: --variant OUTDIR: an empty value (name a folder, e.g. '.')\n");
            return 2;
        }
        return write_variant(argv[2], argv[3], argv[4], argv[5]);
    }
    if (argv[1][0] == '-') {
        fprintf(stderr, "torusrt-genscenes: unknown option '%s'\n", shown(argv[1]));
        usage(stderr);
        return 2;
    }
    const char *outdir = argv[1];
    if (!*outdir) { /* not "the current folder": '' + "/NAME.nff" is the root folder */
        fprintf(stderr, "torusrt-genscenes: OUTDIR: an empty value (name a folder, e.g. '.')\n");
        return 2;
    }
    struct stat dir; /* a folder that is not there: a usage error, as a missing OUTDIR is */
    const char *why = NULL;
    if (stat(outdir, &dir) != 0) why = errno == ENOENT ? "no such folder (make it first)" : strerror(errno);
    else if (!S_ISDIR(dir.st_mode)) why = "not a folder";
    if (why) {
        fprintf(stderr, "torusrt-genscenes: OUTDIR '%s': %s\n", shown(outdir), why);
        return 2;
    }
    for (int a = 2; a < argc; ++a) {
        if (find_scene(argv[a]) < 0) {
            fprintf(stderr, "torusrt-genscenes: unknown scene '%s' (see --list)\n", shown(argv[a]));
            return 2;
        }
        for (int b = 2; b < a; ++b) /* one file written twice would be counted as two scenes */
            if (strcmp(argv[b], argv[a]) == 0) {
                fprintf(stderr, "torusrt-genscenes: scene '%s' named twice; name it once\n", shown(argv[a]));
                return 2;
            }
    }
    int failed = 0, written = 0;
    if (argc == 2) {
        for (int i = 0; i < NSCENES; ++i) {
            if (write_one(outdir, &SCENES[i]) != 0) ++failed;
            else ++written;
        }
    } else {
        for (int a = 2; a < argc; ++a) {
            if (write_one(outdir, &SCENES[find_scene(argv[a])]) != 0) ++failed;
            else ++written;
        }
    }
    printf("torusrt-genscenes: wrote %d scene%s to %s\n", written, written == 1 ? "" : "s", outdir);
    return failed ? 1 : 0;
}
