package org.handsim.files;

import java.io.IOException;
import java.nio.file.FileAlreadyExistsException;
import java.nio.file.Files;
import java.nio.file.LinkOption;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributes;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.nio.file.attribute.UserPrincipal;
import java.util.Set;

/**
 * A folder where HandSim keeps what a later command trusts without checking it against its
 * source again (the runnable jar's models, tessellated meshes): a real folder (not a link) of
 * this user, or root, that neither its group nor others may write, in a parent of the same kind.
 * Anyone who could write there could change what a simulation computes. (The resident server's
 * socket folder is stricter, mode 700 exactly, since its logs must not be read either:
 * {@code server.Client.unsafe}.)
 */
public final class PrivateFolder {
    private PrivateFolder() {}

    /**
     * Makes {@code dir} (and missing parents) with mode 700 if it is not there, then says whether
     * it and its parent are private to {@code me} ({@link #isPrivateTo}).
     */
    public static boolean ensure(Path dir, UserPrincipal me) {
        try {
            Path parent = dir.getParent();
            if (parent != null && !Files.isDirectory(parent)) {
                Files.createDirectories(parent, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
            }
            if (!Files.isDirectory(dir)) {
                try {
                    Files.createDirectory(dir, PosixFilePermissions.asFileAttribute(PosixFilePermissions.fromString("rwx------")));
                } catch (FileAlreadyExistsException raced) {
                    // made by another command meanwhile: judged below as any existing folder
                }
            }
        } catch (IOException | UnsupportedOperationException e) {
            return false;
        }
        return isPrivateTo(dir, me) && (dir.getParent() == null || isPrivateTo(dir.getParent(), me));
    }

    /** {@link #ensure(Path, UserPrincipal)} for the user this JVM runs as. */
    public static boolean ensure(Path dir) {
        try {
            UserPrincipal me = dir.getFileSystem().getUserPrincipalLookupService().lookupPrincipalByName(System.getProperty("user.name"));
            return ensure(dir, me);
        } catch (IOException | UnsupportedOperationException | SecurityException e) {
            return false;
        }
    }

    /** Whether {@code p} is a real folder of {@code me} (or root) that nobody else may write. */
    public static boolean isPrivateTo(Path p, UserPrincipal me) {
        try {
            PosixFileAttributes a = Files.readAttributes(p, PosixFileAttributes.class, LinkOption.NOFOLLOW_LINKS);
            Set<PosixFilePermission> perms = a.permissions();
            return a.isDirectory() && (a.owner().equals(me) || a.owner().getName().equals("root"))
                && !perms.contains(PosixFilePermission.GROUP_WRITE) && !perms.contains(PosixFilePermission.OTHERS_WRITE);
        } catch (IOException | UnsupportedOperationException e) {
            return false;
        }
    }
}
