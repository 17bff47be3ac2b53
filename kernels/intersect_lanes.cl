// Ray casts for the lanes' rays (lanes.cl). Traversal is per ray by nature:
// at width 1 these are intersect.cl's functions; at width > 1 the spheres
// outside the tree (all of a small scene) are tested for all lanes at once,
// one sphere per step (the lanes' form of intersect.cl's ray-sphere test),
// and the tree is walked lane by lane with intersect.cl's traversal: lanes'
// rays go through different nodes, and a node's four boxes are one vector
// test already.

#if ORB_LANES == 1

LANE_FN void lanes_intersect(const SceneView* scene, lv3 o, lv3 d, lint self, lmask lanes, lfloat* t, lint* id)
{
    const Hit hit = intersect_scene(scene, o, d, self);
    *t = hit.t;
    *id = hit.id;
}

LANE_FN lmask lanes_light_visible(const SceneView* scene, lv3 o, lv3 d, lint self, lint light, lmask lanes)
{
    return light_visible(scene, o, d, self, light);
}

#else

ORB_DEFINE_SPHERE_DISTANCE(LANE_FN, lfloat, lint, lv3, lv3, ORB_MISS_MASKED, lanes_sphere_distance)

// The closest sphere along each lane's ray in `lanes`: *id -1 where nothing is hit.
LANE_FN void lanes_intersect(const SceneView* scene, lv3 o, lv3 d, lint self, lmask lanes, lfloat* t_out, lint* id_out)
{
    lfloat best = (lfloat)(ORB_NO_HIT);
    lint id = (lint)(-1);
    for (int p = 0; p < scene->outside_packet_count; ++p) {
        SCENE_MEM const SpherePacket* packet = &scene->packets[p];
        for (int lane = 0; lane < 4; ++lane) {
            const float radius2 = packet_lane(&packet->radius2, lane);
            if (radius2 < 0.0f) break;  // padding lanes come last
            const int sphere = 4 * p + lane;
            const lv3 centre = lv3_make((lfloat)(packet_lane(&packet->centre_x, lane)),
                                        (lfloat)(packet_lane(&packet->centre_y, lane)),
                                        (lfloat)(packet_lane(&packet->centre_z, lane)));
            const lfloat t = lanes_sphere_distance(o, d, centre, (lfloat)(radius2), self == sphere);
            const lmask closer = t < best;
            best = lselect(best, t, closer);
            id = lselect(id, (lint)(sphere), closer);
        }
    }
#if ORB_BVH
    // Each lane starts from its closest hit outside the tree, as
    // intersect_scene does, so the traversal prunes by it.
    if (scene->bvh_node_count > 0) {
        ORB_FOR_EACH_LANE(l, lanes)
        {
            const float3 lane_o = lane_v3(o, l), lane_d = lane_v3(d, l);
            if (!(all(isfinite(lane_o)) && all(isfinite(lane_d)))) continue;
            BestHit lane_best;
            best_init(&lane_best);
#if ORB_SCALAR_TRAVERSAL
            lane_best.t = lane_f(best, l);
            lane_best.id = lane_i(id, l);
#else
            lane_best.t.x = lane_f(best, l);
            lane_best.id.x = lane_i(id, l);
#endif
            traverse_bvh(&lane_best, scene, lane_o, lane_d, lane_i(self, l));
            const Hit hit = best_hit(&lane_best);
            set_lane_f(best, l, hit.t);
            set_lane_i(id, l, hit.id);
        }
    }
#endif
    *t_out = best;
    *id_out = id;
}

// Shadow rays: whether sphere `light` (-1: the environment) is the first
// thing along each lane's ray. Without a tree the closest hit over the few
// spheres is as quick; with one, each lane's any-hit traversal stops at the
// first blocker.
LANE_FN lmask lanes_light_visible(const SceneView* scene, lv3 o, lv3 d, lint self, lint light, lmask lanes)
{
#if ORB_BVH
    if (scene->bvh_node_count > 0) {
        lmask visible = mask_of(false);
        ORB_FOR_EACH_LANE(l, lanes)
        set_lane_i(visible, l, light_visible(scene, lane_v3(o, l), lane_v3(d, l), lane_i(self, l), lane_i(light, l)) ? -1 : 0);
        return visible;
    }
#endif
    lfloat t;
    lint first;
    lanes_intersect(scene, o, d, self, lanes, &t, &first);
    return mask_and(lanes, first == light);
}

#endif
