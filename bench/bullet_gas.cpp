// bullet_gas.cpp: the peer of vroc's gas benchmark (issue 27): the same objects,
// run by Bullet 3 (Debian's libbullet-dev) at its usual fixed step of 1/60 s, for
// the same simulated time.
//
//   bullet_gas SCENE.txt [--step S]
//
// SCENE.txt is what `bench_sim --gas N --export SCENE.txt` writes: every object with
// its shape (a sphere, a box, or the convex hull vroc collides with, its vertices
// about the centre of mass), mass (negative: static), centre of mass, orientation,
// velocity and angular velocity, and the simulated time to run (frames x time_step).
// Bullet's world is its default one (btDbvtBroadphase, the default collision
// configuration, btSequentialImpulseConstraintSolver), with no gravity, as in the
// gas; restitution 1 and no friction, as vroc's elastic frictionless objects.
//
// Prints one line of name=value fields: objects, steps, sim_seconds (simulated),
// setup_s (building the world), wall_s (stepping it: the figure to compare with
// vroc's frames), steps_per_s, and peak_rss_mb (VmHWM of /proc/self/status).
#include <btBulletDynamicsCommon.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <vector>

static double now()
{
    using clk = std::chrono::steady_clock;
    return std::chrono::duration<double>(clk::now().time_since_epoch()).count();
}

static double peak_rss_mb()
{
    FILE *f = std::fopen("/proc/self/status", "r");
    char line[256];
    double kb = 0;
    while (f && std::fgets(line, sizeof line, f))
        if (std::sscanf(line, "VmHWM: %lf kB", &kb) == 1) break;
    if (f) std::fclose(f);
    return kb / 1024;
}

int main(int argc, char **argv)
{
    if (argc < 2) {
        std::fprintf(stderr, "usage: bullet_gas SCENE.txt [--step S]\n");
        return 2;
    }
    double step = 1.0 / 60;
    for (int i = 2; i + 1 < argc; i += 2)
        if (!std::strcmp(argv[i], "--step")) step = std::atof(argv[i + 1]);
    FILE *in = std::fopen(argv[1], "r");
    if (!in) {
        std::perror(argv[1]);
        return 1;
    }
    int n = 0;
    double time_step = 0;
    long frames = 0;
    if (std::fscanf(in, "vroc-scene %d %lf %ld", &n, &time_step, &frames) != 3) {
        std::fprintf(stderr, "bullet_gas: %s is not a scene bench_sim exported\n", argv[1]);
        return 1;
    }
    double t0 = now();
    btDefaultCollisionConfiguration config;
    btCollisionDispatcher dispatcher(&config);
    btDbvtBroadphase broadphase;
    btSequentialImpulseConstraintSolver solver;
    btDiscreteDynamicsWorld world(&dispatcher, &broadphase, &solver, &config);
    world.setGravity(btVector3(0, 0, 0));
    std::vector<std::unique_ptr<btCollisionShape>> shapes;
    std::vector<std::unique_ptr<btRigidBody>> bodies;
    std::vector<std::unique_ptr<btDefaultMotionState>> motions;
    for (int i = 0; i < n; i++) {
        char kind[16];
        double mass;
        if (std::fscanf(in, "%15s %lf", kind, &mass) != 2) {
            std::fprintf(stderr, "bullet_gas: object %d is malformed\n", i);
            return 1;
        }
        btCollisionShape *shape = nullptr;
        if (!std::strcmp(kind, "sphere")) {
            double r;
            if (std::fscanf(in, "%lf", &r) != 1) return 1;
            shape = new btSphereShape(r);
        } else if (!std::strcmp(kind, "box")) {
            double x, y, z;
            if (std::fscanf(in, "%lf %lf %lf", &x, &y, &z) != 3) return 1;
            shape = new btBoxShape(btVector3(x, y, z));
        } else {
            int nv;
            if (std::fscanf(in, "%d", &nv) != 1) return 1;
            auto *hull = new btConvexHullShape();
            for (int k = 0; k < nv; k++) {
                double x, y, z;
                if (std::fscanf(in, "%lf %lf %lf", &x, &y, &z) != 3) return 1;
                hull->addPoint(btVector3(x, y, z), k + 1 == nv);
            }
            shape = hull;
        }
        shapes.emplace_back(shape);
        double c[3], q[4], v[3], w[3];
        if (std::fscanf(in, "%lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf", &c[0], &c[1],
                        &c[2], &q[0], &q[1], &q[2], &q[3], &v[0], &v[1], &v[2], &w[0], &w[1],
                        &w[2]) != 13)
            return 1;
        btTransform at(btQuaternion(q[1], q[2], q[3], q[0]), btVector3(c[0], c[1], c[2]));
        double m = mass < 0 ? 0 : mass;
        btVector3 inertia(0, 0, 0);
        if (m > 0) shape->calculateLocalInertia(m, inertia);
        motions.emplace_back(new btDefaultMotionState(at));
        btRigidBody::btRigidBodyConstructionInfo info(m, motions.back().get(), shape, inertia);
        info.m_restitution = 1;
        info.m_friction = 0;
        auto *b = new btRigidBody(info);
        if (m > 0) {
            b->setLinearVelocity(btVector3(v[0], v[1], v[2]));
            b->setAngularVelocity(btVector3(w[0], w[1], w[2]));
        }
        bodies.emplace_back(b);
        world.addRigidBody(b);
    }
    std::fclose(in);
    double setup = now() - t0;
    double sim = time_step * (double)frames;
    long steps = (long)(sim / step + 0.5);
    double t1 = now();
    for (long k = 0; k < steps; k++) world.stepSimulation(step, 1, step);
    double wall = now() - t1;
    std::printf("objects=%d steps=%ld step=%.6g sim_seconds=%.6g setup_s=%.4g wall_s=%.6g "
                "steps_per_s=%.6g peak_rss_mb=%.1f\n",
                n, steps, step, sim, setup, wall, (double)steps / wall, peak_rss_mb());
    for (auto &b : bodies) world.removeRigidBody(b.get());
    return 0;
}
